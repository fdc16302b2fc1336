// The Waterloo CGL package's Cook-Torrance shading (M. A. J. Sweeney, "The
// Waterloo CGL Ray Tracing Package", University of Waterloo CS-85-35, 1985,
// section 9.9, after Cook and Torrance 1981): the Beckmann facet
// distribution D, the geometric attenuation G, the Fresnel reflectance looked
// up in the surface's 66 x 33 table by the angle between V and H, and the
// per-light term
//
//   Psi(I, L, dw) = I (N.L) dw (k_s S + k_d D_lambda),
//   S = (F / pi) D G / ((N.L)(N.V)),
//
// which the tracer applies to every light, and to the reflected ray (I = R,
// L = D_reflect, dw = k_r) and the transmitted ray (I = T, L = -D_refract,
// dw = k_t) as if they were lights. Also the package's external `cook`
// program: the Fresnel table from a normal reflectance (n = (1 + sqrt R) /
// (1 - sqrt R), k = 0) and a complete `cook` surface descriptor.
// docs/cgl/rendering.md (section Cook-Torrance) gives the choices, CGL-Q100
// to CGL-Q108 in docs/cgl/deviations.md.
//
// Nothing here allocates but the generator.
#pragma once
#include <string>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "src/math/vec.h"

namespace prime::cgl {

// The last index of the Fresnel table (66 vectors, 0..65).
inline constexpr int kFresnelLast = kFresnelAngles - 1;

// Beckmann: D = exp(-(tan(arccos(N.H)) / m)^2) / (m^2 (N.H)^4), with
// tan^2(arccos x) = (1 - x^2) / x^2. 0 when N.H <= 0 (H below the surface).
double beckmann(double nh, double m);

// G = min{1, 2(N.H)(N.V)/(V.H), 2(N.H)(N.L)/(V.H)}; 0 when V.H <= 0.
double geometricAttenuation(double nh, double nv, double nl, double vh);

// The Fresnel table's row for the angle theta = arccos(V.H) (CGL-Q101): the
// document's garbled index "arccos(V.H)/(33 pi)" read as int(theta * 130 / pi),
// theta in radians, which maps 0..90 degrees onto 0..65; clamped to 0..65.
int fresnelIndex(double vh);

// The angle of the table's row j (CGL-Q102): theta_j = j * 90 / 65 degrees,
// j = 0..65, 0 degrees first; returned in radians.
double fresnelAngle(int j);

// Section 9.9: the effective index of refraction of a normal reflectance,
// n = (1 + sqrt R) / (1 - sqrt R). R must be in [0, 1).
double effectiveIndex(double normalReflectance);

// The unpolarised Fresnel reflectance of a dielectric (extinction k = 0) of
// index n at the angle of incidence theta (cosine c): with g^2 = n^2 + c^2 - 1,
// F = (1/2) ((g - c)/(g + c))^2 (1 + ((c(g + c) - 1)/(c(g - c) + 1))^2), which
// is the mean of the s and p reflectances. F(0) = ((n-1)/(n+1))^2, F(90) = 1;
// n = 1 gives 0 at every angle (no interface; CGL-Q103).
double fresnelReflectance(double n, double cosTheta);

// The 66 colour-vectors of a cook surface: row j is F at fresnelAngle(j) for
// each wavelength's effective index. Throws std::invalid_argument when a
// sample is outside [0, 1).
std::vector<Spectrum> fresnelTable(const Spectrum& normalReflectance);

// The geometry of one Psi: what does not depend on the wavelength.
struct CookTerms {
  Vec3 h{};       // (V + L) / |V + L|
  double nl = 0;  // N.L
  double nh = 0, vh = 0;
  double d = 0, g = 0;  // Beckmann D, geometric attenuation G
  int fresnel = 0;      // the Fresnel table's row
  // D G / (pi (N.L)(N.V)): S_lambda = F_lambda * s. At N.L = 0 or N.V = 0
  // it is reported as 0 (the product with N.L below is what is used).
  double s = 0;
  // (N.L) S / F = D G / (pi N.V), the factor Psi uses (CGL-Q104: its limit
  // 2 D (N.H) / (pi (V.H)) when N.V = 0; 0 when N.L <= 0 or V.H <= 0).
  double specular = 0;
};

// D, G, the Fresnel row and the specular factor for the unit vectors N, V
// (N.V >= 0, the tracer's turn of N) and L; m the surface's rms slope.
CookTerms cookTerms(const Vec3& n, const Vec3& v, const Vec3& l, double m);

// z += Psi(I, L, dw) = I dw (k_s F_lambda t.specular + k_d (N.L) D_lambda),
// F the table's row t.fresnel. Nothing when N.L <= 0 (CGL-Q105).
void addPsi(Spectrum& z, const Spectrum& intensity, double dw, const CookTerms& t, double ks,
            double kd, const Spectrum& colour, const std::vector<Spectrum>& fresnel);

// The package's `cook <outfile>` utility (Appendix 1 section 9): a complete
// cook surface descriptor.
struct CookDescriptor {
  int count = 1;  // the surface's number in its file
  double reflect = 0.0, refract = 0.0, index = 0.0;
  double diffuse = 0.0, specular = 1.0, m = 0.3;
  // The normal reflectance R: the Fresnel table is made from it, and the
  // normal-colour-vector D_lambda written is R / pi (CGL-Q106: so the
  // document's copper is printed).
  Spectrum reflectance{};
  std::string name = "cook";  // the comment line's text after "* surface: "
};

// The descriptor as a scene file holds it: a comment, the header line, the
// diffuse line, D_lambda, `specular m`, the 66 Fresnel vectors, each vector
// in the 10/10/10/3 layout, numbers "%.4f" as the document prints them.
// Throws std::invalid_argument for a reflectance outside [0, 1).
std::string cookDescriptorText(const CookDescriptor& descriptor);

}  // namespace prime::cgl
