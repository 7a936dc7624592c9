// How links are generated. Every default works on the shared levels with Recast's default agent
// (radius 0.6, height 2.0, climb 0.9): see docs/link-generation.md for what each one does.
#pragma once

#include <vector>

namespace nl {

struct LinkSettings {
    // Edges
    float min_edge_length = 0.4f;  // shorter boundary edges are grouped with the ones they touch
    unsigned min_group_size = 2;   // groups of fewer short edges are dropped (noise)
    unsigned max_group_size = 8;   // longer chains are split
    float sample_spacing = 1.0f;   // take-off samples along a long edge
    // Take-off points
    float falloff_distance = 1.5f;  // how far past a navmesh edge the ground must fall away for the
                                    // edge to be a take-off point (the rim is searched for up to here)
    // Jumps (edge to edge)
    float max_jump_gap = 4.0f;           // widest gap a jump crosses: horizontal, rim to rim
    float min_link_distance = 0.3f;      // narrower gaps are walked, not jumped
    float short_link_distance = 2.0f;    // links shorter than this use the permissive angle limits
    float max_jump_up = 1.5f;            // highest rise a jump may have, floor to floor (and a drop that is
                                         // also a jump back)
    float jump_arc_height = 1.0f;        // apex of the arc above the higher end
    float strict_forward_angle = 35.0f;  // degrees between the link and an edge's outward direction
    float permissive_forward_angle = 60.0f;
    float strict_incline_angle = 45.0f;  // degrees between the link and the take-off surface's plane
    float permissive_incline_angle = 70.0f;
    // No jump where walking is about as short: a jump is not generated when its ends are joined on
    // foot by a walk of at most walk_factor x its length + walk_distance.
    float walk_factor = 1.5f;
    float walk_distance = 2.0f;
    // Drops (edge to floor)
    float max_drop_distance = 5.0f;                          // deepest drop, floor to floor
    std::vector<float> drop_angles = {0.0f, -30.0f, 30.0f};  // rotations of the outward direction, degrees
    float drop_steepness = 60.0f;  // how steeply the landing probe falls, degrees below horizontal
    // Both
    float merge_distance = 0.6f;    // links whose both ends are this close are one link
    float clearance_margin = 0.1f;  // fraction of the path left out at each end of the clearance test
    unsigned arc_segments = 12;     // pieces of the jump arc in the clearance test
};

// Every setting but drop_angles, by name (what the settings files read and write).
struct NamedFloatSetting {
    const char* name;
    float LinkSettings::*field;
};
struct NamedWholeSetting {
    const char* name;
    unsigned LinkSettings::*field;
};
inline constexpr NamedFloatSetting kFloatSettings[] = {
    {"min_edge_length", &LinkSettings::min_edge_length},
    {"sample_spacing", &LinkSettings::sample_spacing},
    {"falloff_distance", &LinkSettings::falloff_distance},
    {"max_jump_gap", &LinkSettings::max_jump_gap},
    {"min_link_distance", &LinkSettings::min_link_distance},
    {"short_link_distance", &LinkSettings::short_link_distance},
    {"max_jump_up", &LinkSettings::max_jump_up},
    {"jump_arc_height", &LinkSettings::jump_arc_height},
    {"strict_forward_angle", &LinkSettings::strict_forward_angle},
    {"permissive_forward_angle", &LinkSettings::permissive_forward_angle},
    {"strict_incline_angle", &LinkSettings::strict_incline_angle},
    {"permissive_incline_angle", &LinkSettings::permissive_incline_angle},
    {"max_drop_distance", &LinkSettings::max_drop_distance},
    {"drop_steepness", &LinkSettings::drop_steepness},
    {"merge_distance", &LinkSettings::merge_distance},
    {"clearance_margin", &LinkSettings::clearance_margin},
    {"walk_factor", &LinkSettings::walk_factor},
    {"walk_distance", &LinkSettings::walk_distance},
};
inline constexpr NamedWholeSetting kWholeSettings[] = {
    {"min_group_size", &LinkSettings::min_group_size},
    {"max_group_size", &LinkSettings::max_group_size},
    {"arc_segments", &LinkSettings::arc_segments},
};

// Throws InvalidArgument about the first bad field ("max_jump_gap is -1 (...)", see fail_field).
void validate(const LinkSettings& settings);

}  // namespace nl
