#pragma once
// The names of a closed set (an enum) as scene files, the command line, --stats and messages
// say them: one table per enum, and one way to go from a value to its name, from a name to
// its value, and to the "a, b or c" a message lists. The table's length is checked against
// the enum at compile time, so an enumerator added without a name does not compile (and
// cannot index past the end of the table at run time).
#include "core/text.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

namespace names_detail {

// Whether V is one of its enum's enumerators. The compiler spells a template argument that
// is an enumerator by its name ("V = rt::AccelKind::fast") and any other value as a cast,
// a closing parenthesis and a number ("V = (rt::AccelKind)8"): GCC and Clang both do (the
// technique of magic_enum). A name never ends in ")8" (an anonymous namespace's
// "(anonymous namespace)::" comes before it), so the enum's own definition is the only
// place that says how many values it has. (Clang 14 spells even an enumerator as a cast
// when its enum is a member of a class template: such an enum counts 0 and its table fails
// to compile, loudly; none of the library's enums is one.)
template <auto V>
constexpr bool is_enumerator() {
    constexpr std::string_view signature = __PRETTY_FUNCTION__;
    const std::string_view value = signature.substr(signature.rfind('='));
    const std::size_t close = value.rfind(')');
    if (close == std::string_view::npos) return true;
    bool digits = false;  // only digits (and a sign, and the "]" GCC ends with) after it: a cast
    for (const char c : value.substr(close + 1)) {
        if (c >= '0' && c <= '9')
            digits = true;
        else if (c != '-' && c != ']' && c != ' ')
            return true;
    }
    return !digits;
}

// The enumerators of E, counted from 0 up to the first value that is not one (every enum
// named here numbers its values 0, 1, 2, ... in order, as an enum does by default).
template <class E, std::size_t k = 0>
constexpr std::size_t enumerator_count() {
    if constexpr (k < 256 && is_enumerator<E(k)>())
        return enumerator_count<E, k + 1>();
    else
        return k;
}

}  // namespace names_detail

template <class E, std::size_t N>
class Names {
public:
    constexpr explicit Names(const std::array<const char*, N>& names) : names_(names) {}

    // The name of e.
    constexpr const char* operator[](E e) const { return names_[std::size_t(e)]; }
    // The value a name means, or nothing for a name of no value.
    constexpr std::optional<E> find(std::string_view name) const {
        for (std::size_t k = 0; k < N; ++k)
            if (name == names_[k]) return E(k);
        return std::nullopt;
    }
    // Every value, in the enum's order.
    constexpr std::array<E, N> values() const {
        std::array<E, N> all{};
        for (std::size_t k = 0; k < N; ++k) all[k] = E(k);
        return all;
    }
    // Every name, for a command-line check (CLI::IsMember).
    std::vector<std::string> all() const { return {names_.begin(), names_.end()}; }
    // "a, b or c": what a message says it expected.
    std::string list() const { return or_list(names_); }
    static constexpr std::size_t size() { return N; }

private:
    std::array<const char*, N> names_;
};

// The table of E's names, one per enumerator in the enum's order:
//     inline constexpr auto kAccelNames = names_of<AccelKind>({"none", "bvh-sort", ...});
template <class E, std::size_t N>
constexpr Names<E, N> names_of(const char* const (&names)[N]) {
    static_assert(names_detail::enumerator_count<E>() == N, "one name per enumerator of the enum, in its order");
    std::array<const char*, N> table{};
    for (std::size_t k = 0; k < N; ++k) table[k] = names[k];
    return Names<E, N>(table);
}

}  // namespace rt
