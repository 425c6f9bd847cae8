// fairness 9.3 fail: a box that asks for its own transformed box: the recursion never ends
// The stack overflows and the test program crashes; the grade must count the crashed test
// as failed, name it, and keep the chapter's denominator.
// expect: crashed
// @body
    Box inner = transform_box(to_world, box);  // never returns: the same call again
    inner.expand(to_world.t);
    return inner;
