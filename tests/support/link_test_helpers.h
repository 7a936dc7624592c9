// Small things the link tests share.
#pragma once

#include <navlink/navlink.h>

#include <vector>

#include "links/link.h"

namespace nl::test {

// A world destroyed with its owner.
struct WorldPtr {
    nl_world* world = nullptr;
    WorldPtr() = default;
    WorldPtr(const WorldPtr&) = delete;
    WorldPtr& operator=(const WorldPtr&) = delete;
    ~WorldPtr() { nl_world_destroy(world); }
};

// The links of one kind, in order.
inline std::vector<Link> links_of_kind(const std::vector<Link>& links, LinkKind kind) {
    std::vector<Link> out;
    for (const Link& l : links)
        if (l.kind == kind) out.push_back(l);
    return out;
}

}  // namespace nl::test
