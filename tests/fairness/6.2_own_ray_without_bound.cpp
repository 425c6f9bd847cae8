// fairness 6.2 fail: the shadow ray built by hand from offset_origin, leaving the point's error behind
// Exercise 6.1's start and the right interval, so every small scene renders as the reference
// does; but a big sphere's hit lies farther off the surface than offset_origin's step, and
// its shadow rays find the sphere itself. The big ground through direct_light must say so.
// @body
    const LightSample l = light.sample(sp.p);
    if (l.color == Color(0) || glm::dot(sp.side, l.direction) <= 0) return Color(0);
    const Real end = std::isfinite(l.distance) ? std::nextafter(l.distance, Real(0)) : kInfinity;
    const SpawnedRay shadow{Ray{offset_origin(sp.p, sp.side), l.direction}, Interval{0, end}};
    if (in_shadow(scene, shadow, light_index, l.color, context)) return Color(0);
    Color c = lambert(sp.diffuse, l.color, sp.n, l.direction);
    if (sp.material.has_specular()) {
        ++context.counters.specular_terms;
        c += blinn_phong_highlight(sp.material.specular, sp.material.exponent, l.color, sp.n, l.direction, sp.v);
    }
    return c;
