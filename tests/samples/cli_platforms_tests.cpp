// navlink simulate --platforms: passengers ride a shuttle, a turning disc and a lift that the host
// moves by their timetables; every one arrives, those who came while their platform was away waited
// for it, and each gets on and off by its gangways.
#include <regex>

#include "cli_fixture.h"

using nl::test::navlink;
using nl::test::ProgramRun;
using nl::test::simulated_arrival;

namespace {

// The seconds of the first line matching `pattern` (after its leading time), or -1.
double first_time_of(const std::string& out, const std::string& pattern) {
    std::smatch m;
    if (!std::regex_search(out, m, std::regex("\n +([0-9.]+) s  " + pattern))) return -1.0;
    return std::stod(m[1]);
}

}  // namespace

TEST_CASE(
    "navlink simulate --platforms: every passenger arrives, waiting for the shuttle and the lift, and the platforms "
    "are drawn") {
    const std::string dir = nl::test::scratch_dir("simulate_platforms");
    const ProgramRun run = navlink({"simulate", "--platforms"}, dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    INFO(run.out);
    for (const char* passenger : {"ferry rider", "disc rider", "disc crosser", "lift rider"}) {
        INFO(passenger);
        const nl::test::SimulatedArrival a = simulated_arrival(run.out, passenger);
        CHECK(a.outcome == "arrived");
        CHECK(a.to_goal < 0.5);  // each has a destination of its own (the navmesh lies 0.3 m above the floor)
    }
    // The ferry and the lift had left when their riders came: they waited at the gangway, got on when
    // it came back, and got off at the other side (the ferry's rider jumps up the far ledge's step).
    const double ferry_wait = first_time_of(run.out, R"(ferry rider +waits for the shuttle at )");
    const double ferry_on =
        first_time_of(run.out, R"(ferry rider +walks onto the shuttle from .* after waiting [0-9.]+ s\n)");
    const double ferry_off = first_time_of(run.out, R"(ferry rider +jumps off the shuttle from )");
    CHECK(ferry_wait > 0.0);
    CHECK(ferry_on > ferry_wait + 3.0);  // the shuttle was on the far side
    CHECK(ferry_off > ferry_on + 4.0);   // the crossing takes 4 s
    const double lift_wait = first_time_of(run.out, R"(lift rider +waits for the lift at )");
    const double lift_on = first_time_of(run.out, R"(lift rider +walks onto the lift from )");
    const double lift_off =
        first_time_of(run.out, R"(lift rider +walks off the lift from \([^)]*\) to \([0-9.]+, 0\.4, )");
    CHECK(lift_wait > 0.0);
    CHECK(lift_on > lift_wait + 1.0);
    CHECK(lift_off > lift_on + 4.0);  // up to the upper floor, 4 m above the apron
    CHECK(simulated_arrival(run.out, "ferry rider").links == "1 jump, 1 manual link");
    CHECK(simulated_arrival(run.out, "ferry rider").waited > 5.0);
    CHECK(simulated_arrival(run.out, "lift rider").waited > 2.0);
    // On the disc by the gangway to its axis; off it by the one under its edge, once the disc has
    // turned it to the exit.
    CHECK(first_time_of(run.out, R"(disc crosser +waits on the disc for its way off at )") > 0.0);
    CHECK(first_time_of(run.out, R"(disc crosser +walks off the disc from .* after waiting [0-9.]+ s\n)") > 0.0);
    CHECK(simulated_arrival(run.out, "disc crosser").links == "2 manual links");
    CHECK(simulated_arrival(run.out, "disc rider").links == "1 manual link");
    CHECK(nl::test::is_png(dir + "/platforms.png", 1600));

    // Two steps a second still catch the disc's exit and every platform.
    const ProgramRun coarse = navlink({"simulate", "--platforms", "--hz", "2", "--out-dir", dir}, dir);
    CHECK_MESSAGE(coarse.exit_code == 0, coarse.out);
    // Too little time: the ferry is still on its way, exit status 1.
    const ProgramRun cut = navlink({"simulate", "--platforms", "--seconds", "10", "--out-dir", dir}, dir);
    CHECK(cut.exit_code == 1);
    CHECK(simulated_arrival(cut.out, "ferry rider").outcome == "on its way");
}
