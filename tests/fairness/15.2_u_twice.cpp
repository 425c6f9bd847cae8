// fairness 15.2 fail: u used for both edges (a slip of uv.x for uv.y): every sample lies on the
// light's diagonal, a line light, so the penumbra has the wrong shape
// @body
    return light.position + uv.x * light.edge_a + uv.x * light.edge_b;
