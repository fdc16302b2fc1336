"""compare_images.py A.png B.png: how close two renders of one scene
are, pixel by pixel (A: prime trace, B: POV-Ray of the exported scene).
Prints: mean absolute difference (bytes, 0-255, all channels), how many
pixels differ at all and by how much at most, the share of pixels whose
largest channel difference is <= 8 and > 32, and the share of pixels black in
one picture and not in the other (coverage). No `|` in the output: it goes
into a markdown table. Needs Pillow and numpy."""
import sys

import numpy as np
from PIL import Image

a = np.asarray(Image.open(sys.argv[1]).convert("RGB"), dtype=np.int32)
b = np.asarray(Image.open(sys.argv[2]).convert("RGB"), dtype=np.int32)
if a.shape != b.shape:
    print("sizes differ: %s vs %s" % (a.shape, b.shape))
    sys.exit(1)
d = np.abs(a - b)
m = d.max(axis=2)
blackA = a.max(axis=2) == 0
blackB = b.max(axis=2) == 0
print("mean diff %.2f; %d px differ (max %d); %.1f%% within 8; %.1f%% off by > 32; coverage %.2f%%" % (
    d.mean(), int((m > 0).sum()), int(m.max()), 100.0 * (m <= 8).mean(),
    100.0 * (m > 32).mean(), 100.0 * (blackA != blackB).mean()))
