#pragma once
// f(the alternative v holds), for a std::variant on a hot path. std::visit does the same, but
// GCC 12 compiles it to a table of function pointers: an indirect call per query that can
// inline nothing, two of them (structure, then shape) on every ray. This is a chain of
// index tests the compiler turns into a switch, each arm inlined. Book §10.5 measures it.
#include <cstddef>
#include <utility>
#include <variant>

namespace rt {

namespace detail {

template <class R, std::size_t I, class V, class F>
[[gnu::always_inline]] inline R dispatch_from(const V& v, F& f) {
    if constexpr (I + 1 == std::variant_size_v<V>) {
        return f(*std::get_if<I>(&v));
    } else {
        if (v.index() == I) return f(*std::get_if<I>(&v));
        return dispatch_from<R, I + 1>(v, f);
    }
}

}  // namespace detail

// Takes any type derived from a std::variant (Shape is one) as that variant.
template <class... T, class F>
[[gnu::always_inline]] inline decltype(auto) dispatch(const std::variant<T...>& v, F&& f) {
    using R = decltype(f(*std::get_if<0>(&v)));
    return detail::dispatch_from<R, 0>(v, f);
}

}  // namespace rt
