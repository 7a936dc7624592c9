#include "link_shape.h"

#include <algorithm>

namespace nl::picture {

std::vector<Point3> traversal_curve(nl_link_kind kind, const float start[3], const float end[3], const float apex[3],
                                    int samples) {
    // A quadratic Bezier: through the apex at its middle for a jump (control 2 apex - mid), bending
    // out over the landing at the take-off height for a drop, straight otherwise.
    Point3 control;
    for (int k = 0; k < 3; ++k) control[k] = 0.5f * (start[k] + end[k]);
    // A jump a host added has no arc of its own (nl_link_add gives it its higher end as apex): it is
    // drawn straight rather than bent back from that end.
    const bool arc = apex[1] > std::max(start[1], end[1]) + 1e-3f;
    if (kind == NL_LINK_JUMP && arc) {
        for (int k = 0; k < 3; ++k) control[k] = 2.0f * apex[k] - 0.5f * (start[k] + end[k]);
    } else if (kind == NL_LINK_DROP) {
        control = {end[0], start[1], end[2]};
        if (end[1] > start[1]) control = {start[0], end[1], start[2]};  // climbed back up: rise first
    }
    std::vector<Point3> out;
    out.reserve(static_cast<size_t>(samples) + 1);
    for (int i = 0; i <= samples; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(samples), u = 1.0f - t;
        Point3 p;
        for (int k = 0; k < 3; ++k) p[k] = u * u * start[k] + 2.0f * u * t * control[k] + t * t * end[k];
        out.push_back(p);
    }
    return out;
}

}  // namespace nl::picture
