#pragma once
// Viewing rays (book §1, course §9.2). The four free functions are the chapter 01
// exercises; their reference bodies live in solutions/ch01_viewing_rays.cpp.
#include "core/ray.hpp"

namespace rt {

enum class Projection { orthographic, perspective };

// The camera frame: the eye looks along -w, v is up, u is right.
struct Basis {
    Vec3 u, v, w;
};

// The view window [l, r] x [b, t] in uv coordinates.
struct Window {
    Real l, r, b, t;
};

// Exercise 1.1: the frame from a view direction and an up vector.
Basis camera_basis(const Vec3& view_direction, const Vec3& up);

// Exercise 1.2: the windowing transform. (x, y) is a continuous position in the image,
// with pixel (i, j) covering [i, i+1) x [j, j+1): its centre is (i + 0.5, j + 0.5). j counts
// up from the bottom row, like v.
Vec2 window_point(Real x, Real y, int nx, int ny, const Window& window);

// Exercise 1.3: the orthographic viewing ray through window point (u_s, v_s).
Ray orthographic_ray(const Vec3& eye, const Basis& uvw, const Vec2& uv);

// Exercise 1.4: the perspective viewing ray through window point (u_s, v_s), with the
// image plane at distance d in front of the eye (w_s = -d).
Ray perspective_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv);

// Where one camera ray starts in each of its dimensions. A pinhole camera ignores the lens
// position and a closed shutter the time, so chapters 01-05 pay nothing for them.
struct CameraSample {
    Vec2 film;      // continuous image position, (i + 0.5, j + 0.5) at the centre of pixel (i, j)
    Vec2 lens{0};   // on the lens disk, in [-1, 1]^2 (depth of field)
    Real time = 0;  // in [0, 1) of the shutter interval (motion blur)
};

// A camera fixed to one image size: what the render loop asks for rays.
struct View {
    Projection projection;
    Vec3 eye;
    Basis uvw;
    Window window;
    Real focal_distance;
    int nx, ny;

    Ray ray(const CameraSample& sample) const;
    Ray pixel_ray(int i, int j) const { return ray({Vec2(Real(i) + Real(0.5), Real(j) + Real(0.5))}); }
};

// A camera as a scene describes it, independent of the image size. The window keeps the
// given vertical extent and takes its width from the image's aspect ratio, so pixels
// are square at any --width/--height.
struct Camera {
    Projection projection = Projection::perspective;
    Vec3 eye{0, 0, 0};
    Vec3 target{0, 0, -1};
    Vec3 up{0, 1, 0};
    Real vertical_fov_degrees = 45;  // perspective only
    Real window_height = 2;          // orthographic only: t - b
    Real focal_distance = 1;         // perspective: distance to the image plane

    // Throws std::invalid_argument for a camera that cannot see: eye on the target, up along
    // the view, a field of view or window outside its range.
    void validate() const;
    View view(int nx, int ny) const;
};

}  // namespace rt
