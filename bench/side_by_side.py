"""side_by_side.py A.png B.png OUT.png: A (left) and B (right) side by side,
each auto-levelled (its 99.5th-percentile channel value becomes 255) so dark
scenes can be compared by eye. Needs Pillow (Debian: python3-pil)."""
import sys

from PIL import Image


def level(im):
    px = sorted(max(p) for p in im.getdata())
    top = px[int(len(px) * 0.995)] or 1
    return im.point(lambda v: min(255, int(v * 255 / top)))


a = level(Image.open(sys.argv[1]).convert("RGB"))
b = level(Image.open(sys.argv[2]).convert("RGB"))
out = Image.new("RGB", (a.width + b.width + 10, max(a.height, b.height)), (40, 40, 40))
out.paste(a, (0, 0))
out.paste(b, (a.width + 10, 0))
out.save(sys.argv[3])
