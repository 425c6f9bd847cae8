#pragma once
// Where a secondary ray (shadow, reflection, refraction) starts, so that it does not hit the
// surface it leaves because of rounding (book §6.3, course §9.5's epsilon). Three ways, kept
// side by side because chapter 06 measures them against each other (the acne table).
#include "core/interval.hpp"
#include "core/names.hpp"
#include "core/ray.hpp"

#include <cstdint>

namespace rt {

enum class OffsetMethod : std::uint8_t {
    normal,  // start at p + epsilon n: a fixed distance off the surface
    course,  // start at p, search t in [epsilon, max]: course §9.5 as printed
    robust,  // start at offset_origin(p, n) (exercise 6.1), search from 0: no constant to choose
};
inline constexpr auto kOffsetMethodNames = names_of<OffsetMethod>({"normal", "course", "robust"});

struct Offset {
    OffsetMethod method = OffsetMethod::robust;
    Real epsilon = Real(1e-4);  // the constant of the normal and course methods
};

// Exercise 6.1: the origin for a ray leaving point p on the side n points to (n unit, the
// geometric normal turned towards that side), after Waechter and Binder (Ray Tracing Gems,
// chapter 6). Each coordinate moves a fixed number of units in the last place of its own
// magnitude, so the step grows with the rounding error of p wherever p is; coordinates near
// zero, where units in the last place vanish, move a fixed small distance instead. Graded on
// each step's side and size (at most twice `ulps` units in the last place, or the fixed
// step), and to the bit only where every way of taking it is exact: from (1, 0, 0) along
// (1, 0, 0), x moves by exactly `ulps` units of epsilon.
Vec3 offset_origin(const Vec3& p, const Vec3& n);

// The constants of offset_origin for float and for double (see book §6.3).
template <class R>
struct OffsetConstants;
template <>
struct OffsetConstants<float> {
    static constexpr float origin = 1.0f / 32;         // below this magnitude: a fixed step
    static constexpr float fixed_step = 1.0f / 65536;  // that step, times n
    static constexpr std::int32_t ulps = 256;          // elsewhere: this many units in the last place, times n
};
template <>
struct OffsetConstants<double> {
    static constexpr double origin = 1.0 / 32;
    static constexpr double fixed_step = 0x1p-40;  // double's rounding is 2^29 times finer than float's ...
    static constexpr std::int64_t ulps = 4096;     // ... and a larger margin in ulps still moves p by ~1e-12 of itself
};

// A ray ready to cast: where it starts and which t it accepts.
struct SpawnedRay {
    Ray ray;
    Interval interval;
};

// Where a secondary ray leaves a surface: the point p, the unit geometric normal `side`
// turned towards the side the ray goes to, and `error`, how far the computed p may lie off
// the true surface, as the shape that found it reports it (HitRecord::error). The three
// travel together, and the constructor wants all three, so that no ray can leave a point
// without its bound (a shape with no error of its own says 0 where it builds the point).
struct SurfacePoint {
    SurfacePoint(const Vec3& p, const Vec3& side, Real error) : p(p), side(side), error(error) {}
    Vec3 p;
    Vec3 side;
    Real error;
};

// The ray from surface point `from` in `direction` (any length), accepted up to t = max,
// made by the method of `o`. The robust method starts at least `from.error` out along the
// side, since offset_origin's step follows p's coordinates, not the shape's size: a ground
// sphere of radius 1000 centred 1000 below the origin has hit points near y = 0, where the
// step is 2^-40 (2^-45 just past |y| = 1/32), and errors the size of a unit in the last
// place of 1000 (book §6.3).
inline SpawnedRay spawn_ray(const SurfacePoint& from, const Vec3& direction, Real max, const Offset& o, Real time = 0) {
    const Vec3& p = from.p;
    const Vec3& n_side = from.side;
    switch (o.method) {
        case OffsetMethod::normal:
            return {Ray{p + o.epsilon * n_side, direction, time}, Interval{0, max}};
        case OffsetMethod::course:
            return {Ray{p, direction, time}, Interval{o.epsilon, max}};
        case OffsetMethod::robust:
            break;
    }
    const Vec3 q = offset_origin(p, n_side);
    // Where the step already clears the bound, keep it: most hits, and every hit of a shape
    // that reports no error (0), start exactly where exercise 6.1 puts them.
    if (!(glm::dot(q - p, n_side) < from.error)) return {Ray{q, direction, time}, Interval{0, max}};
    return {Ray{offset_origin(p + from.error * n_side, n_side), direction, time}, Interval{0, max}};
}

}  // namespace rt
