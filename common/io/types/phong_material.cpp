// A material: the Blinn-Phong terms of chapter 05, a checkerboard in x and z, a mirror colour
// (chapter 07), its glossy width (chapter 17) and a dielectric's index of refraction and Beer attenuation (chapter 08).
#include "io/scene_types.hpp"

namespace rt {

Material read_material(const Fields& f) {
    Material m;
    m.ior = float(f.number("ior", limits::index_of_refraction, 0));
    // Clear glass unless told otherwise: a dielectric's default diffuse colour is black.
    m.diffuse = f.color("diffuse", limits::reflectance, m.is_dielectric() ? Color(0) : m.diffuse);
    m.specular = f.color("specular", limits::reflectance, m.specular);
    m.exponent = float(f.number("exponent", limits::exponent, Real(m.exponent)));
    m.checker = f.color("checker", limits::reflectance, m.checker);
    m.checker_size = float(f.length("checker_size", 0));
    if (f.has("checker") != f.has("checker_size")) f.fail("", "'checker' and 'checker_size' go together");
    m.mirror = f.color("mirror", limits::reflectance, m.mirror);
    m.glossy = float(f.number("glossy", limits::glossy_width, 0));
    if (f.has("glossy") && !m.has_mirror()) f.fail("glossy", "only a mirror (with 'mirror') has a glossy width");
    m.attenuation = f.color("attenuation", limits::reflectance, m.attenuation);
    if (f.has("attenuation") && !m.is_dielectric()) f.fail("attenuation", "only a dielectric (with 'ior') has it");
    if (m.is_dielectric() && f.has("mirror"))
        f.fail("mirror", "a dielectric reflects by Schlick's R, not a mirror colour");
    f.done();
    return m;
}

}  // namespace rt
