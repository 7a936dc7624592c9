#include "navigable_level.h"

#include <cstdio>

#include "clock.h"
#include "level_frame_options.h"
#include "navmesh_setup.h"
#include "progress_bar.h"
#include "sample_error.h"

namespace nl::cli {

using nl::samples::now_ms;

NavigableLevel::NavigableLevel(const std::string& level_path, const std::optional<std::string>& navmesh_path,
                               const nl_agent_type& body, const std::string& recast_json, bool for_drawing,
                               const std::optional<std::string>& plugin_path, const samples::LevelFrame& frame) {
    // First: a plugin that does not load fails before the level is read and built.
    if (plugin_path) world_.load_plugin(*plugin_path);
    double start = now_ms();
    level_ = samples::load_level_file(world_.get(), level_path, for_drawing, frame);
    times_.load_ms = now_ms() - start;
    start = now_ms();
    if (navmesh_path) {
        navmesh_ = samples::add_navmesh_from_obj(world_.get(), *navmesh_path, body);
    } else {
        ProgressBar bar;
        try {
            navmesh_ = samples::build_navmesh(world_.get(), body, recast_json, {}, ProgressBar::callback, &bar);
        } catch (const samples::SampleError& e) {
            // The library names nl_mesh_def's field; the tool's way to set it:
            if (std::string(e.what()).find("metres_per_unit") == std::string::npos) throw;
            throw samples::SampleError(std::string(e.what()) + "; navlink's --units says " + level_path +
                                       "'s unit (cm, mm, in, ft, km or the metres in one unit)");
        }
        nl_navmesh_info info = nl_navmesh_info_init();
        if (NL_SUCCEEDED(nl_navmesh_get_info(world_.get(), navmesh_, &info))) hint_level_frame(info, level_path);
    }
    times_.navmesh_ms = now_ms() - start;
}

NavigableLevel::NavigableLevel(const levelgen::GeneratedLevel& generated, const std::string& name,
                               const nl_agent_type& body, const std::string& recast_json) {
    double start = now_ms();
    level_ = samples::add_generated_level(world_.get(), generated, name);
    times_.load_ms = now_ms() - start;
    start = now_ms();
    ProgressBar bar;
    navmesh_ = samples::build_navmesh(world_.get(), body, recast_json, {}, ProgressBar::callback, &bar);
    times_.navmesh_ms = now_ms() - start;
}

nl_link_generation_report NavigableLevel::generate_links(const nl_link_settings& settings) {
    nl_link_generation_report report{};
    report.size = sizeof report;
    ProgressBar bar;
    samples::check(nl_navmesh_generate_links(world_.get(), navmesh_, &settings, ProgressBar::callback, &bar, &report),
                   "generating links");
    return report;
}

}  // namespace nl::cli
