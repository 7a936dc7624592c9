#include "links/link_settings.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace nl {
namespace {

void check(bool ok, float value, const char* field, const char* rule) {
    if (!ok || !std::isfinite(value)) fail_field(ErrorCode::InvalidArgument, field, " is ", value, " (", rule, ")");
}

}  // namespace

void validate(const LinkSettings& s) {
    check(s.min_edge_length >= 0.0f, s.min_edge_length, "min_edge_length", "must be >= 0");
    if (s.min_group_size < 1 || s.max_group_size < s.min_group_size || s.max_group_size > 1000)
        fail_field(ErrorCode::InvalidArgument, "max_group_size is ", s.max_group_size, " with min_group_size ",
                   s.min_group_size, " (must satisfy 1 <= min <= max <= 1000)");
    check(s.sample_spacing >= 0.05f, s.sample_spacing, "sample_spacing", "must be >= 0.05 m");
    check(s.falloff_distance > 0.0f && s.falloff_distance <= 10.0f, s.falloff_distance, "falloff_distance",
          "must be in (0, 10] m");
    check(s.max_jump_gap > 0.0f && s.max_jump_gap <= 100.0f, s.max_jump_gap, "max_jump_gap", "must be in (0, 100] m");
    check(s.min_link_distance >= 0.0f && s.min_link_distance < s.max_jump_gap, s.min_link_distance, "min_link_distance",
          "must be >= 0 and below max_jump_gap");
    check(s.short_link_distance >= 0.0f, s.short_link_distance, "short_link_distance", "must be >= 0");
    check(s.max_jump_up >= 0.0f, s.max_jump_up, "max_jump_up", "must be >= 0");
    check(s.jump_arc_height > 0.0f && s.jump_arc_height <= 50.0f, s.jump_arc_height, "jump_arc_height",
          "must be in (0, 50] m");
    for (const auto& [value, name] : {std::pair{s.strict_forward_angle, "strict_forward_angle"},
                                      std::pair{s.permissive_forward_angle, "permissive_forward_angle"},
                                      std::pair{s.strict_incline_angle, "strict_incline_angle"},
                                      std::pair{s.permissive_incline_angle, "permissive_incline_angle"}})
        check(value >= 0.0f && value <= 90.0f, value, name, "must be in [0, 90] degrees");
    check(s.walk_factor >= 0.0f && s.walk_factor <= 100.0f, s.walk_factor, "walk_factor", "must be in [0, 100]");
    check(s.walk_distance >= 0.0f && s.walk_distance <= 1000.0f, s.walk_distance, "walk_distance",
          "must be in [0, 1000] m");
    check(s.max_drop_distance > 0.0f && s.max_drop_distance <= 1000.0f, s.max_drop_distance, "max_drop_distance",
          "must be in (0, 1000] m");
    if (s.drop_angles.size() > 16)
        fail_field(ErrorCode::InvalidArgument, "drop_angles has ", s.drop_angles.size(), " entries (at most 16)");
    for (size_t i = 0; i < s.drop_angles.size(); ++i) {
        const std::string name = "drop_angles[" + std::to_string(i) + "]";
        check(std::fabs(s.drop_angles[i]) <= 80.0f, s.drop_angles[i], name.c_str(), "must be in [-80, 80] degrees");
    }
    check(s.drop_steepness >= 10.0f && s.drop_steepness <= 90.0f, s.drop_steepness, "drop_steepness",
          "must be in [10, 90] degrees");
    check(s.merge_distance >= 0.0f, s.merge_distance, "merge_distance", "must be >= 0");
    check(s.clearance_margin >= 0.0f && s.clearance_margin < 0.5f, s.clearance_margin, "clearance_margin",
          "must be in [0, 0.5)");
    if (s.arc_segments < 2 || s.arc_segments > 64)
        fail_field(ErrorCode::InvalidArgument, "arc_segments is ", s.arc_segments, " (must be 2..64)");
}

}  // namespace nl
