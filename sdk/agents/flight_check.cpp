#include "agents/flight_check.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "links/clearance.h"
#include "links/link_settings.h"

namespace nl {
namespace {

// Pieces an arc is cut into: its sagitta over each, which the body's height span grows by, stays
// a few centimetres for the jumps agents take.
constexpr int kArcPieces = 16;

}  // namespace

bool flight_is_clear(const LinkMotion& flight, float radius, float height, const Level& level) {
    std::vector<Vec3> points;
    float slack = 0.0f;
    switch (flight.kind()) {
        case MotionKind::Arc:
            // x and z move uniformly in time and y is quadratic: a piece strays from its chord most at
            // its middle time, by exactly the midpoint's distance from the chord's.
            for (int k = 0; k <= kArcPieces; ++k) points.push_back(flight.at(flight.duration() * float(k) / kArcPieces));
            for (int k = 0; k < kArcPieces; ++k) {
                const Vec3 mid = flight.at(flight.duration() * (float(k) + 0.5f) / kArcPieces);
                slack = std::max(slack, std::fabs(mid.y() - 0.5f * (points[k].y() + points[k + 1].y())));
            }
            break;
        case MotionKind::Fall:
            points.assign(flight.fall_points().begin(), flight.fall_points().end());
            break;
        case MotionKind::Line:
            points = {flight.from(), flight.to()};
            break;
    }
    const Body body{radius, height};
    const std::vector<SweepPiece> pieces =
        sweep_pieces(PathPoints{points.data(), points.size(), slack}, LinkSettings{}.clearance_margin, radius);
    if (pieces.empty()) return true;
    std::vector<BodyStretch> stretches;
    stretches.reserve(pieces.size());
    for (const SweepPiece& piece : pieces) stretches.push_back(stretch_of(piece, body, radius));
    std::vector<uint8_t> cleared(stretches.size());
    level.bodies_clear(stretches.data(), static_cast<uint32_t>(stretches.size()), &radius, 1, cleared.data());
    return std::all_of(cleared.begin(), cleared.end(), [](uint8_t c) { return c >= 1; });
}

}  // namespace nl
