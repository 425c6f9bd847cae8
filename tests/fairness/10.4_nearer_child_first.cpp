// fairness 10.4 pass: the search visits the child whose box centre lies nearer along the ray
// first (the book's further work, §10.9); the best hit is still passed down and ties are still
// settled by hit_primitive's one order, so the hits are brute force's
// @body
    if (is_primitive(ref)) return hit_primitive(surfaces, ref, ray, interval, best);
    const CourseBvhNode& n = node(ref);
    if (!hit_box(n.box, ray, interval)) return false;
    const Box a = box(n.left), b = box(n.right);
    const Real to_a = glm::dot((a.min + a.max) * Real(0.5) - ray.origin, ray.direction);
    const Real to_b = glm::dot((b.min + b.max) * Real(0.5) - ray.origin, ray.direction);
    const BvhRef first = to_a <= to_b ? n.left : n.right, second = to_a <= to_b ? n.right : n.left;
    const bool hit_first = hit_node(surfaces, first, ray, interval, best);
    if (hit_first) interval.max = best.t;
    const bool hit_second = hit_node(surfaces, second, ray, interval, best);
    return hit_first || hit_second;
