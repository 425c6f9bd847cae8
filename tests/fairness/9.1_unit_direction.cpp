// fairness 9.1 fail: the object-space direction made unit
// The ray points the right way, but t now measures another length than in the world: a hit's
// t no longer carries over, and the closest hit among instances is picked by the wrong numbers.
// @body
    return Ray{to_object.point(ray.origin), glm::normalize(to_object.vector(ray.direction)), ray.time};
