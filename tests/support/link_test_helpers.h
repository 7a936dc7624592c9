// Small things the link tests share.
#pragma once

#include <vector>

#include "links/link.h"

namespace nl::test {

// The links of one kind, in order.
inline std::vector<Link> links_of_kind(const std::vector<Link>& links, LinkKind kind) {
    std::vector<Link> out;
    for (const Link& l : links)
        if (l.kind == kind) out.push_back(l);
    return out;
}

}  // namespace nl::test
