// {"diffuse": [r, g, b], "specular": [r, g, b], "exponent": p}: the Blinn-Phong material.
#include "io/scene_types.hpp"

namespace rt {

Material read_material(const Fields& f) {
    f.only({"diffuse", "specular", "exponent"});
    Material m;
    m.diffuse = f.color("diffuse", limits::reflectance, m.diffuse);
    m.specular = f.color("specular", limits::reflectance, m.specular);
    m.exponent = float(f.number("exponent", limits::exponent, Real(m.exponent)));
    return m;
}

}  // namespace rt
