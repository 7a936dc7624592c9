#include "agents/flight_check.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "links/clearance.h"
#include "links/link_settings.h"

namespace nl {
namespace {

// Pieces a flight is cut into at least: an arc's sagitta over each, which the body's height span
// grows by, stays a few centimetres for the jumps agents take.
constexpr int kLeastPieces = 16;
// More where meshes move fast near it, so that a mesh placed at a piece's middle time strays at
// most this far from there while the body flies the piece (the body grows by it)...
constexpr float kMostStray = 0.02f;
// ...up to this many pieces; past it the stray, and the body, grow instead.
constexpr int kMostPieces = 256;

// The moving meshes that may come near a flight: those whose points, however they move in its
// time, can reach the box around it.
std::vector<MeshMotion> moving_near(const std::vector<MeshMotion>& moving, const Aabb& flight, float duration) {
    std::vector<MeshMotion> near;
    for (const MeshMotion& m : moving) {
        if (!m.moves()) continue;
        const Vec3 origin = m.now.translation();
        const float reach = m.reach + m.fastest_point() * duration;
        const Vec3 closest = origin.cwiseMax(flight.min).cwiseMin(flight.max);
        if ((closest - origin).norm() <= reach) near.push_back(m);
    }
    return near;
}

}  // namespace

bool flight_is_clear(const LinkMotion& flight, float radius, float height, const Level& level,
                     const std::vector<MeshMotion>& moving, bool on_proven_arc) {
    const float duration = flight.duration();
    Aabb box;
    for (int k = 0; k <= kLeastPieces; ++k) box.grow(flight.at(duration * float(k) / kLeastPieces));
    if (flight.kind() == MotionKind::Fall)
        for (const Vec3& p : flight.fall_points()) box.grow(p);
    box.min -= Vec3(radius, 0.0f, radius);
    box.max += Vec3(radius, height, radius);
    const std::vector<MeshMotion> near = moving_near(moving, box, duration);
    if (on_proven_arc && near.empty()) return true;

    float fastest = 0.0f;
    for (const MeshMotion& m : near) fastest = std::max(fastest, m.fastest_point());
    // A mesh moved by a jump of the host's (or over a step of almost no time) gives no motion to
    // trust: the flight waits for a step that does.
    if (!std::isfinite(fastest * duration)) return false;
    const int count =
        int(std::clamp(std::ceil(fastest * duration / (2.0f * kMostStray)), float(kLeastPieces), float(kMostPieces)));
    // Uniform in time, and at a fall's corners: each piece is then straight, or an arc's piece, in
    // which x and z move uniformly and y is quadratic, so it strays from its chord most at its middle
    // time, by exactly the midpoint's distance from the chord's.
    std::vector<float> times;
    for (int k = 0; k <= count; ++k) times.push_back(duration * float(k) / count);
    for (float t : flight.corner_times()) times.push_back(t);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    std::vector<Vec3> points;
    for (float t : times) points.push_back(flight.at(t));
    float slack = 0.0f, longest = 0.0f;
    for (size_t k = 0; k + 1 < times.size(); ++k) {
        const Vec3 mid = flight.at(0.5f * (times[k] + times[k + 1]));
        slack = std::max(slack, std::fabs(mid.y() - 0.5f * (points[k].y() + points[k + 1].y())));
        longest = std::max(longest, times[k + 1] - times[k]);
    }
    // A mesh placed where it is at a piece's middle time moves at most this far either way while the
    // body flies the piece: the body grows by it, all round.
    const float stray = 0.5f * fastest * longest;

    const Body body{radius + stray, height};
    const std::vector<SweepPiece> pieces =
        sweep_pieces(PathPoints{points.data(), points.size(), slack + stray}, LinkSettings{}.clearance_margin, radius);
    if (pieces.empty()) return true;
    std::vector<BodyStretch> stretches;
    std::vector<MeshPlacement> placements;
    stretches.reserve(pieces.size());
    placements.reserve(pieces.size() * near.size());
    for (const SweepPiece& piece : pieces) {
        stretches.push_back(stretch_of(piece, body, body.radius));
        const float middle = 0.5f * (times[piece.source] + times[piece.source + 1]);
        for (const MeshMotion& m : near) placements.push_back(MeshPlacement{m.mesh, m.after(middle)});
    }
    std::vector<BodyGroup> groups;
    groups.reserve(pieces.size());
    for (uint32_t i = 0; i < pieces.size(); ++i)
        groups.push_back(BodyGroup{stretches[i].bounds, i, 1, placements.data() + i * near.size(),
                                   static_cast<uint32_t>(near.size())});
    std::vector<uint8_t> cleared(stretches.size());
    level.bodies_clear(groups.data(), static_cast<uint32_t>(groups.size()), stretches.data(), &body.radius, 1,
                       cleared.data());
    return std::all_of(cleared.begin(), cleared.end(), [](uint8_t c) { return c >= 1; });
}

}  // namespace nl
