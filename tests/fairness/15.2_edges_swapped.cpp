// fairness 15.2 pass: u along edge_b and v along edge_a, the other way round from the reference:
// the same parallelogram, sampled as evenly (the light's strata are shuffled against the
// pixel's either way), as the header's "u along one edge and v along the other" allows
// @body
    return light.position + uv.x * light.edge_b + uv.y * light.edge_a;
