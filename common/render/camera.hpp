#pragma once
// Viewing rays (book §1, course §9.2). The four free functions are the chapter 01
// exercises; their reference bodies live in solutions/ch01_viewing_rays.cpp.
#include "core/names.hpp"
#include "core/ray.hpp"

#include <cstdint>

namespace rt {

enum class Projection { orthographic, perspective };
inline constexpr auto kProjectionNames = names_of<Projection>({"orthographic", "perspective"});

// The camera frame: the eye looks along -w, v is up, u is right.
struct Basis {
    Vec3 u, v, w;
};

// The view window [l, r] x [b, t] in uv coordinates.
struct Window {
    Real l, r, b, t;
};

// Exercise 1.1: the frame from a view direction and an up vector. Graded within a few machine
// epsilons (unit lengths, right angles, u x v = w, w the reversed unit view direction, u
// level), so any construction passes (Gram-Schmidt, glm::lookAt's); exactly the world axes
// for the standard camera (looking down -z, up +y), where every number is exact.
Basis camera_basis(const Vec3& view_direction, const Vec3& up);

// Exercise 1.2: the windowing transform. (x, y) is a continuous position in the image,
// with pixel (i, j) covering [i, i+1) x [j, j+1): its centre is (i + 0.5, j + 0.5). j counts
// up from the bottom row, like v. Graded within 4 machine epsilons of the window's size
// (|l| + |r| for u, |b| + |t| for v), never by its bits: any arrangement of the map passes,
// the pixel's width first, a blend of the edges, std::fma.
Vec2 window_point(Real x, Real y, int nx, int ny, const Window& window);

// Exercise 1.3: the orthographic viewing ray through window point (u_s, v_s): from
// e + u_s u + v_s v, direction -w exactly. Tested on numbers for which every way of writing
// the sum is exact, so compared exactly.
Ray orthographic_ray(const Vec3& eye, const Basis& uvw, const Vec2& uv);

// Exercise 1.4: the perspective viewing ray through window point (u_s, v_s), with the
// image plane at distance d in front of the eye (w_s = -d). Its direction u_s u + v_s v - d w
// (not normalised) has uvw coordinates (u_s, v_s, -d) to within 8 machine epsilons, however
// far the eye is from the origin: it never goes through the eye's coordinates.
Ray perspective_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv);

// The shape of a thin lens (chapter 16): the course's square, or a round one.
enum class LensShape : std::uint8_t { square, disk };
inline constexpr auto kLensNames = names_of<LensShape>({"square", "disk"});

// Exercise 16.1: a point of the lens from u in [0, 1)^2, in lens coordinates centred on the
// lens's middle. The square: 2u - 1, in [-1, 1)^2. The disk: any map onto the unit disk that
// is uniform (equal areas of u to equal areas of the disk) and keeps strata of u compact
// (each stratum of a 4 x 4 pattern lands in a patch less than 1 across; the polar map's
// outer arcs are 1.41), in any orientation: the tests check these properties, not where a
// particular u lands. Shirley and Chiu's concentric map (book §16.2) is one. The square's
// points are compared exactly for u in halves, quarters and eighths, where every way of
// writing 2u - 1 gives the same bits.
Vec2 lens_point(const Vec2& u, LensShape shape);

// Exercise 16.2: the thin-lens version of perspective_ray: the ray from the point `lens`
// (lens coordinates, as lens_point makes them) of a lens of width `aperture` centred on the
// eye, in the plane of u and v (eye + (aperture / 2)(lens.x u + lens.y v): lens.x along u,
// lens.y along v), through the point that the pinhole ray through window point
// uv meets at distance `focus` in front of the eye (the plane -w . (p - eye) = focus). Every
// such ray through one window point meets the pinhole ray there: that plane is in focus.
// Its direction is scaled as the pinhole ray's is: it reaches that point at t = focus / d,
// as the pinhole ray does (a lens point of (0, 0) gives the pinhole ray itself).
Ray thin_lens_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv, Real aperture, Real focus,
                  const Vec2& lens);

// Exercise 18.1: the time of a ray in stratum k of n equal strata of the shutter interval
// [open, close), at the place u in [0, 1) inside its stratum. Always below close (rounding
// must not push it there), except for an instant shutter, open == close: then open.
// Within rounding, and exactly only where every way is exact (strata of [0, 1) in quarters).
Real shutter_time(int k, int n, Real u, Real open, Real close);

// Where one camera ray starts in each of its dimensions. A pinhole camera ignores the lens
// position, and a scene where nothing moves the time, so chapters 01-05 pay nothing for them.
struct CameraSample {
    Vec2 film;      // continuous image position, (i + 0.5, j + 0.5) at the centre of pixel (i, j)
    Vec2 lens{0};   // on the lens, in lens coordinates: [-1, 1]^2 or the unit disk (depth of field)
    Real time = 0;  // in [open, close) of the shutter interval, on the motion's clock (motion blur)
};

// A camera fixed to one image size: what the render loop asks for rays.
struct View {
    Projection projection;
    Vec3 eye;
    Basis uvw;
    Window window;
    Real focal_distance;
    int nx, ny;
    // Chapter 16: a lens of width `aperture` (0: a pinhole) focused at `focus` in front of the eye.
    Real aperture = 0;
    Real focus = 1;
    LensShape lens = LensShape::square;
    // Chapter 18: the shutter is open from `shutter_open` to `shutter_close` (times in [0, 1],
    // when things that move are where they are at the start and the end of their motion).
    Real shutter_open = 0, shutter_close = 1;

    bool has_lens() const { return aperture > 0; }

    // Inline: the render loop calls it once per camera ray.
    Ray ray(const CameraSample& sample) const {
        const Vec2 uv = window_point(sample.film.x, sample.film.y, nx, ny, window);
        Ray r = projection == Projection::orthographic ? orthographic_ray(eye, uvw, uv)
                : has_lens() ? thin_lens_ray(eye, uvw, focal_distance, uv, aperture, focus, sample.lens)
                             : perspective_ray(eye, uvw, focal_distance, uv);
        r.time = sample.time;
        return r;
    }
    // Through the centre of pixel (i, j) and of the lens, at the shutter's opening.
    Ray pixel_ray(int i, int j) const {
        return ray({Vec2(Real(i) + Real(0.5), Real(j) + Real(0.5)), Vec2(0), shutter_open});
    }
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
    Real aperture = 0;               // chapter 16: lens width, 0 = pinhole (perspective only)
    Real focus_distance = 0;         // where the lens focuses, along the view; 0 = at the target
    LensShape lens = LensShape::square;
    Real shutter_open = 0, shutter_close = 1;  // chapter 18

    // Throws std::invalid_argument for a camera that cannot see: eye on the target, up along
    // the view, a field of view or window outside its range, a lens on an orthographic camera,
    // a shutter that closes before it opens.
    void validate() const;
    View view(int nx, int ny) const;
};

}  // namespace rt
