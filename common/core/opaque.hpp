#pragma once
// Values the optimiser must not see through. Each is an empty asm statement that claims to
// read and change a value where it sits, so the compiler can neither fold what was done to
// the value before it nor fuse it with its neighbours; no instruction is emitted. What
// "where it sits" means is the architecture's: an SSE register on x86-64 ("x"), a SIMD and
// floating-point register on AArch64 ("w"). Elsewhere the value goes through memory ("m"),
// which hides it as well at the cost of a store and a load.
#include "core/interval.hpp"

namespace rt {

#if defined(__x86_64__) || defined(__i386__)
#define RTLAB_OPAQUE_FLOAT "+x"
#elif defined(__aarch64__)
#define RTLAB_OPAQUE_FLOAT "+w"
#else
#define RTLAB_OPAQUE_FLOAT "+m"
#endif

// v, unchanged, but unknown to the optimiser from here on.
template <class T>
inline void opaque(T& v) {
    asm("" : RTLAB_OPAQUE_FLOAT(v));
}

// The same interval, its bounds made two registers. A query that copies its Interval whole
// (to a callee, into a struct) gets it from GCC as one 16-byte load just after the two
// 8-byte stores that spilled it, a failed store forward that stalls the query (a tenth of
// a mesh query that misses); hiding each bound breaks the pairing.
inline Interval in_registers(Interval iv) {
    opaque(iv.min);
    opaque(iv.max);
    return iv;
}

}  // namespace rt
