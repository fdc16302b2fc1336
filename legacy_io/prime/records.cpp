#include "legacy_io/prime/records.h"

#include <string>

namespace prime::io {

int surfaceCount(PrimType type) {
  switch (type) {
    case PrimType::Sphere:
      return 1;
    case PrimType::Cube:
      return 6;
    case PrimType::Cylinder:
      return 3;
    case PrimType::Cone:
      return 2;
    case PrimType::Pyramid:
      return 5;
  }
  return 0;  // not reached: every PrimType is named above
}

const char* primTypeName(PrimType type) {
  switch (type) {
    case PrimType::Sphere:
      return "sphere";
    case PrimType::Cube:
      return "cube";
    case PrimType::Cylinder:
      return "cylinder";
    case PrimType::Cone:
      return "cone";
    case PrimType::Pyramid:
      return "pyramid";
  }
  return "unknown";  // not reached
}

int surfaceCount(char type) {
  const std::optional<PrimType> t = primType(type);
  return t ? surfaceCount(*t) : 0;
}

const char* primTypeName(char type) {
  const std::optional<PrimType> t = primType(type);
  return t ? primTypeName(*t) : "unknown";
}

void encode(ByteWriter& w, const Hue& h) {
  w.putDouble(h.kDR);
  w.putDouble(h.kDT);
  for (double f : h.fDR) w.putDouble(f);
  w.putDouble(h.tT);
  w.putDouble(h.kRH);
  w.putDouble(h.kTH);
  w.putDouble(h.indx);
}

void encode(ByteWriter& w, const ObjRecord& o) {
  for (char c : o.opCode) w.putChar(static_cast<std::uint8_t>(c));
  w.putInt16(o.l);
  w.putInt16(o.r);
}

void encode(ByteWriter& w, const ObjHeader& h) {
  w.putInt16(h.numEntries);
  w.putInt16(h.boundVol);
  encode(w, h.hue);
}

static void encodeMatrix(ByteWriter& w, const Matrix4& m) {
  for (const auto& row : m)
    for (double v : row) w.putDouble(v);
}

void encode(ByteWriter& w, const PrimRecord& p, PrimLayout layout) {
  w.putChar(static_cast<std::uint8_t>(p.type));
  if (layout == PrimLayout::WordAligned) w.putZeros(1);  // -a: doubles start on an even byte
  encodeMatrix(w, p.transform);
  encodeMatrix(w, p.inverse);
  for (const auto& surface : p.map) {
    w.putInt16(surface[kOut]);
    w.putInt16(surface[kIn]);
  }
  w.putInt16(p.priority);
  w.putDouble(p.indx);
}

void encode(ByteWriter& w, const MapHeader& h) {
  w.putInt16(h.uScale);
  w.putInt16(h.vScale);
}

Hue decodeHue(ByteReader& r) {
  Hue h;
  h.kDR = r.getDouble("hue.kDR");
  h.kDT = r.getDouble("hue.kDT");
  h.fDR[0] = r.getDouble("hue.fDR[R]");
  h.fDR[1] = r.getDouble("hue.fDR[G]");
  h.fDR[2] = r.getDouble("hue.fDR[B]");
  h.tT = r.getDouble("hue.tT");
  h.kRH = r.getDouble("hue.kRH");
  h.kTH = r.getDouble("hue.kTH");
  h.indx = r.getDouble("hue.indx");
  return h;
}

ObjRecord decodeObj(ByteReader& r) {
  ObjRecord o;
  for (auto& c : o.opCode) c = static_cast<char>(r.getChar("Obj.opCode"));
  o.l = r.getInt16("Obj.l");
  o.r = r.getInt16("Obj.r");
  return o;
}

ObjHeader decodeObjHeader(ByteReader& r) {
  ObjHeader h;
  h.numEntries = r.getInt16("ObjHeader.numEntries");
  h.boundVol = r.getInt16("ObjHeader.boundVol");
  h.hue = decodeHue(r);
  return h;
}

static Matrix4 decodeMatrix(ByteReader& r, const char* name) {
  Matrix4 m{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      m[i][j] = r.getDouble(std::string("Prim.") + name + "[" + std::to_string(i) + "][" +
                            std::to_string(j) + "]");
  return m;
}

PrimRecord decodePrim(ByteReader& r, PrimLayout layout) {
  PrimRecord p;
  p.type = static_cast<char>(r.getChar("Prim.type"));
  if (layout == PrimLayout::WordAligned) r.skip(1, "Prim alignment byte");
  p.transform = decodeMatrix(r, "transform");
  p.inverse = decodeMatrix(r, "inverse");
  for (auto& surface : p.map) {
    surface[kOut] = r.getInt16("Prim.map[][Out]");
    surface[kIn] = r.getInt16("Prim.map[][In]");
  }
  p.priority = r.getInt16("Prim.priority");
  p.indx = r.getDouble("Prim.indx");
  return p;
}

MapHeader decodeMapHeader(ByteReader& r) {
  MapHeader h;
  h.uScale = r.getInt16("MapHeader.uScale");
  h.vScale = r.getInt16("MapHeader.vScale");
  return h;
}

}  // namespace prime::io
