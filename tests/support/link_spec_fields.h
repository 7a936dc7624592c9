// The fields and settings issue 13 adds to the generator, in ONE place, so the tests compile against
// today's code and switch themselves on when a field lands: each FIELD below is found by name at
// compile time (`has_...`), read as an optional (`..._of`, nullopt while the field does not exist)
// and set when it exists (`set_...`, false while it does not). If a name changes, change it here.
//
//   LinkRequirements::length            horizontal distance end to end (gap becomes rim to rim)
//   BakeReport::rejected_walkable       jumps whose ends are walked about as quickly
//   BakeReport::rejected_too_shallow    drops no deeper than max_climb (walked, floor to floor)
//   BakeReport::rejected_too_deep       drops deeper than max_drop_distance (floor to floor)
//   LinkSettings::walk_factor           a jump is not made when walking is at most
//   LinkSettings::walk_distance           walk_factor x length + walk_distance (defaults 1.5, 2 m)
#pragma once

#include <optional>
#include <type_traits>
#include <utility>

namespace nl::test::spec {

#define NL_SPEC_OPTIONAL_FIELD(NAME)                                                                        \
    template <class T, class = void>                                                                    \
    struct has_##NAME : std::false_type {};                                                             \
    template <class T>                                                                                  \
    struct has_##NAME<T, std::void_t<decltype(std::declval<const T&>().NAME)>> : std::true_type {};     \
    template <class T>                                                                                  \
    std::optional<double> NAME##_of(const T& value) {                                                   \
        if constexpr (has_##NAME<T>::value) return static_cast<double>(value.NAME);                     \
        else return std::nullopt;                                                                       \
    }                                                                                                   \
    template <class T>                                                                                  \
    bool set_##NAME(T& value, double x) {                                                               \
        if constexpr (has_##NAME<T>::value) {                                                           \
            value.NAME = static_cast<std::decay_t<decltype(value.NAME)>>(x);                            \
            return true;                                                                                \
        } else {                                                                                        \
            (void)value, (void)x;                                                                       \
            return false;                                                                               \
        }                                                                                               \
    }

NL_SPEC_OPTIONAL_FIELD(length)                // LinkRequirements
NL_SPEC_OPTIONAL_FIELD(rejected_walkable)     // BakeReport
NL_SPEC_OPTIONAL_FIELD(rejected_too_shallow)  // BakeReport
NL_SPEC_OPTIONAL_FIELD(rejected_too_deep)     // BakeReport
NL_SPEC_OPTIONAL_FIELD(walk_factor)           // LinkSettings
NL_SPEC_OPTIONAL_FIELD(walk_distance)         // LinkSettings

#undef NL_SPEC_OPTIONAL_FIELD

// The spec's defaults for the new settings (used when the settings do not have them yet).
constexpr double kDefaultWalkFactor = 1.5;
constexpr double kDefaultWalkDistance = 2.0;

}  // namespace nl::test::spec
