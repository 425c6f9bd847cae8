#include "render/camera.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

void Camera::validate() const {
    const Vec3 view_direction = target - eye;
    if (view_direction == Vec3(0)) throw std::invalid_argument("camera: eye and target are the same point");
    if (up == Vec3(0)) throw std::invalid_argument("camera: up must not be zero");
    if (!(glm::length(glm::cross(unit_vector(view_direction), unit_vector(up))) > Real(1e-6)))
        throw std::invalid_argument("camera: up is parallel to the view direction");
    if (projection == Projection::perspective && !(vertical_fov_degrees > 0 && vertical_fov_degrees < 180))
        throw std::invalid_argument("camera: vertical field of view must be in (0, 180) degrees");
    if (projection == Projection::orthographic && !(window_height > 0))
        throw std::invalid_argument("camera: orthographic window height must be > 0");
    if (!(aperture >= 0)) throw std::invalid_argument("camera: aperture must be >= 0");
    if (aperture > 0 && projection == Projection::orthographic)
        throw std::invalid_argument("camera: a lens (aperture > 0) needs a perspective camera");
    if (!(focus_distance >= 0)) throw std::invalid_argument("camera: focus distance must be >= 0");
    if (!(shutter_open >= 0 && shutter_open <= shutter_close && shutter_close <= 1))
        throw std::invalid_argument("camera: the shutter must open and close at times 0 <= open <= close <= 1");
}

View Camera::view(int nx, int ny) const {
    validate();
    const Vec3 view_direction = target - eye;
    const Real aspect = Real(nx) / Real(ny);
    Real half_height;
    if (projection == Projection::perspective) {
        const Real half_angle = glm::radians(vertical_fov_degrees) / Real(2);
        half_height = focal_distance * std::tan(half_angle);
    } else {
        half_height = window_height / Real(2);
    }
    const Real half_width = half_height * aspect;
    View v{projection, eye,
           // Unit vectors first: the student's basis then never squares a huge or tiny one.
           camera_basis(unit_vector(view_direction), unit_vector(up)),
           Window{-half_width, half_width, -half_height, half_height}, focal_distance, nx, ny};
    v.aperture = aperture;
    v.focus = focus_distance > 0 ? focus_distance : glm::length(view_direction);
    v.lens = lens;
    v.shutter_open = shutter_open;
    v.shutter_close = shutter_close;
    return v;
}

}  // namespace rt
