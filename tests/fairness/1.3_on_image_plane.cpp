// fairness 1.3 fail: the origin one unit ahead of the eye, on an image plane at w = -1
// An orthographic ray starts on the plane through the eye (book §1.4): a scene between the
// eye and that plane would be lost.
// @body
    return Ray{eye + uv.x * uvw.u + uv.y * uvw.v - uvw.w, -uvw.w};
