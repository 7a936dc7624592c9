// The moving-platforms scene: the default level with, north of its lower floor, grounds for three
// platforms its host moves. An apron continues the lower floor north; past it, a 10 m chasm to a
// ledge a step higher, crossed by a shuttle; a pit where a disc turns, with an exit ledge beyond it;
// and a trench under an upper floor 4 m up, climbed by a lift. Here is where everything is, when
// each platform stands where, the gangways placed while it does, and the passengers who ride them:
// plain data, put in a world by moving_platforms.h.
#pragma once

#include <navlink/navlink.h>

#include <string>
#include <vector>

#include "agent_profile.h"
#include "level_generator.h"
#include "platform_timetable.h"

namespace nl::samples {

// A cross link between the ground and a platform, as its host places it: while the platform stands
// where its timetable has it at `placed_at`, so that it holds while the platform stands there again.
struct Gangway {
    std::string name;
    nl_link_kind kind;  // NL_LINK_MANUAL: walked (no gap asked); NL_LINK_JUMP: measured from its ends
    bool onto;          // from the ground onto the platform, else off it onto the ground
    double placed_at;   // seconds
    Point start, end;   // in the world, at `placed_at`
};

struct PlatformLayout {
    std::string name;               // "shuttle", "disc", "lift"
    levelgen::GeneratedLevel body;  // its triangles in its own space, its deck's top at y = 0
    Timetable timetable;
    std::vector<Gangway> gangways;
};

struct Passenger {
    AgentProfile profile;  // named for where it goes
    Point start;
    Point destination;               // in the world at time 0
    std::string destination_name;    // "across the chasm"
    bool destination_rides = false;  // on a platform: it moves with it
};

struct PlatformsLevel {
    levelgen::GeneratedLevel level;  // what stands still: the default level and the platforms' grounds
    std::vector<PlatformLayout> platforms;
    std::vector<Passenger> passengers;
};

// The shuttle leaves the near ledge just before its passenger gets there (it waits for it to come
// back) and lets it off with a jump up the far ledge's step; the lift is on its way down when its
// passenger arrives; the disc's exit is under the disc's edge once a turn, at 9 s, 25 s, ... `seed`
// is the default level's.
PlatformsLevel generate_platforms_level(uint32_t seed);

}  // namespace nl::samples
