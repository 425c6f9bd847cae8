#pragma once
// The one way the lab acts on a closed set of kinds (shapes, search structures): dispatch
// for a query every kind answers with its own overload, match for a decision written out
// case by case. Neither has a default: a kind nobody handles does not compile.
//
// dispatch: f(the alternative v holds), for a std::variant on a hot path. std::visit does the same, but
// GCC 12 compiles it to a table of function pointers: an indirect call per query that can
// inline nothing, two of them (structure, then shape) on every ray. This is a chain of
// index tests the compiler turns into a switch, each arm inlined. Book §10.5 measures it.
#include <cstddef>
#include <type_traits>
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

// The cases of a match: one callable per kind.
template <class... F>
struct Cases : F... {
    using F::operator()...;
};
template <class... F>
Cases(F...) -> Cases<F...>;

namespace detail {
struct NotAKind {};
}  // namespace detail

// dispatch over cases written out for each kind: a missing kind does not compile, and
// neither does a catch-all (a generic lambda would take any kind, a new one included,
// without anyone deciding what it should do).
template <class... T, class... F>
decltype(auto) match(const std::variant<T...>& v, F&&... cases) {
    Cases all{std::forward<F>(cases)...};
    static_assert((std::is_invocable_v<decltype(all)&, const T&> && ...), "match: a case for every kind");
    static_assert(!std::is_invocable_v<decltype(all)&, const detail::NotAKind&>, "match: no catch-all case");
    return dispatch(v, all);
}

}  // namespace rt
