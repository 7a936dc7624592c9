#include "registry/navmesh_registry.h"

#include <algorithm>
#include <shared_mutex>

#include "links/link_placement.h"
#include "links/tile_links.h"

namespace nl {
namespace {

thread_local bool generating_on_this_thread = false;

}  // namespace

NavMeshRegistry::GenerationOnThisThread::GenerationOnThisThread() {
    if (generating_on_this_thread)
        fail(ErrorCode::InvalidArgument,
             "links cannot be generated or updated from inside another generation or update "
             "(its progress callback or a plugin): it could wait for itself");
    generating_on_this_thread = true;
}

NavMeshRegistry::GenerationOnThisThread::~GenerationOnThisThread() { generating_on_this_thread = false; }

NavMeshRegistry::GenerationTurn::GenerationTurn(std::shared_ptr<std::mutex> turn) : turn_(std::move(turn)) {
    turn_->lock();
}

NavMeshRegistry::GenerationTurn::~GenerationTurn() { turn_->unlock(); }

NavMeshRegistry::Entry& NavMeshRegistry::entry(Handle navmesh) {
    Entry* e = navmeshes_.find(navmesh);
    if (!e) fail_stale("navmesh", navmesh);
    return *e;
}

const NavMeshRegistry::Entry& NavMeshRegistry::entry(Handle navmesh) const {
    return const_cast<NavMeshRegistry*>(this)->entry(navmesh);
}

std::shared_ptr<CarrierFrame> NavMeshRegistry::frame_of_mesh(Handle mesh) const {
    std::shared_ptr<CarrierFrame> found;
    navmeshes_.for_each([&](Handle, const Entry& e) {
        if (!found && e.frame && e.frame->mesh() == mesh) found = e.frame;
    });
    return found;
}

Handle NavMeshRegistry::add(std::shared_ptr<const NavMesh> navmesh, Handle carrier, const Transform& to_world,
                            NavMeshProvenance made_for, TileInputs tiles) {
    Entry e;
    e.navmesh = std::move(navmesh);
    e.made_for = std::move(made_for);
    e.tiles = std::move(tiles);
    std::unique_lock lock(mutex_);
    if (carrier != Handle{}) {
        e.frame = frame_of_mesh(carrier);
        if (!e.frame) e.frame = std::make_shared<CarrierFrame>(carrier, to_world);
    }
    return navmeshes_.insert(std::move(e));
}

HeldPtr<const CarrierFrame> NavMeshRegistry::frame(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return entry(navmesh).frame;
}

NavMeshRegistry::Placed NavMeshRegistry::placed(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    const Entry& e = entry(navmesh);
    return Placed{e.navmesh, e.frame};
}

bool NavMeshRegistry::carried_by(Handle mesh) const {
    std::shared_lock lock(mutex_);
    return frame_of_mesh(mesh) != nullptr;
}

Handle NavMeshRegistry::riding(Handle mesh, const AgentType& body) const {
    std::shared_lock lock(mutex_);
    Handle found;
    navmeshes_.for_each([&](Handle h, const Entry& e) {
        if (found == Handle{} && e.frame && e.frame->mesh() == mesh && same_body(e.navmesh->agent(), body)) found = h;
    });
    return found;
}

void NavMeshRegistry::move_carrier(Handle mesh, const Transform& to_world) {
    std::shared_lock lock(mutex_);
    if (const std::shared_ptr<CarrierFrame> frame = frame_of_mesh(mesh)) frame->move(to_world);
}

void NavMeshRegistry::remove(Handle navmesh) {
    std::unique_lock lock(mutex_);
    Entry& e = entry(navmesh);
    for (Handle id : e.link_ids) links_.erase(id);
    navmeshes_.erase(navmesh);
    // The cross links that land on it lead nowhere now. Last: should one of these erasures fail to
    // allocate, the navmesh is gone all the same, and a link left behind never holds.
    navmeshes_.for_each(
        [&](Handle, Entry& other) { erase_links(other, [&](const Link& l) { return l.landing_navmesh == navmesh; }); });
}

TileInputs NavMeshRegistry::tile_inputs(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return entry(navmesh).tiles;
}

namespace {

// A link end on `navmesh` placed again: parked (kNoPolygon) while the tile it belongs to (`tile`, else
// the one its point lies in) is not loaded, or when it is off the navmesh, so that no path takes it.
// The tile of the polygon it is placed on becomes its tile if it had none.
uint32_t placed_again(const NavMesh& navmesh, const Vec3& point, uint32_t was, std::optional<TileCoord>& tile) {
    const TileLayout& layout = navmesh.tiles();
    if (tile ? !layout.holds(*tile) : !layout.holds_point(point.x(), point.z())) return kNoPolygon;
    Link probe;
    probe.start = probe.end = point;
    probe.start_polygon = probe.end_polygon = was;
    try {
        place_saved_link(navmesh, probe);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidArgument) throw;
        return kNoPolygon;
    }
    if (!tile && layout.grid.tiled()) tile = layout.tiles[navmesh.tile_of(probe.start_polygon)];
    return probe.start_polygon;
}

}  // namespace

void NavMeshRegistry::replace_tiles(Handle navmesh, TileInputs tiles, std::shared_ptr<const NavMesh> joined,
                                    const TileLinks* regenerated) {
    std::unique_lock lock(mutex_);
    Entry& e = entry(navmesh);
    // Placed first, stored after: a failure to allocate leaves the navmesh as it was.
    std::vector<std::pair<Link*, Link>> placed;
    for (Handle id : e.link_ids) {
        Link& l = links_.find(id)->link;
        Link again = l;
        again.start_polygon = placed_again(*joined, l.start, l.start_polygon, again.start_tile);
        if (!l.crosses()) again.end_polygon = placed_again(*joined, l.end, l.end_polygon, again.end_tile);
        placed.push_back({&l, again});
    }
    navmeshes_.for_each([&](Handle, Entry& other) {
        for (Handle id : other.link_ids) {
            Link& l = links_.find(id)->link;
            if (l.landing_navmesh != navmesh) continue;
            Link again = l;
            again.end_polygon = placed_again(*joined, l.end, l.end_polygon, again.end_tile);
            placed.push_back({&l, again});
            other.snapshot.reset();
        }
    });
    for (auto& [link, again] : placed) *link = again;
    e.navmesh = std::move(joined);
    e.tiles = std::move(tiles);
    e.snapshot.reset();
    e.path_graph.reset();
    if (!e.last.tile_settings) e.last = LastGeneration{};
    if (regenerated) replace_tile_links(navmesh, e, *regenerated);  // placed on the navmesh just published
}

bool NavMeshRegistry::contains(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return navmeshes_.find(navmesh) != nullptr;
}

HeldPtr<const NavMesh> NavMeshRegistry::navmesh(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return entry(navmesh).navmesh;
}

std::vector<Handle> NavMeshRegistry::handles() const {
    std::shared_lock lock(mutex_);
    std::vector<Handle> out;
    out.reserve(navmeshes_.size());
    navmeshes_.for_each([&](Handle h, const Entry&) { out.push_back(h); });
    return out;
}

Link NavMeshRegistry::placed_on_current(const Entry& e, Link link) const {
    // A link is placed by its writer outside the lock; tiles added or removed meanwhile replaced the
    // navmesh it was placed on. Where a tile may have changed, its ends are placed again here (kept
    // where they still lie, parked off the loaded tiles). A navmesh without tiles never changes.
    if (!e.tiles.empty())
        link.start_polygon = placed_again(*e.navmesh, link.start, link.start_polygon, link.start_tile);
    if (!link.crosses()) {
        if (!e.tiles.empty()) link.end_polygon = placed_again(*e.navmesh, link.end, link.end_polygon, link.end_tile);
    } else if (const Entry* landing = navmeshes_.find(link.landing_navmesh); landing && !landing->tiles.empty()) {
        link.end_polygon = placed_again(*landing->navmesh, link.end, link.end_polygon, link.end_tile);
    }
    return link;
}

Handle NavMeshRegistry::insert_link(Handle navmesh, Entry& e, const Link& link) {
    // Room first (grown geometrically: one more each time copied the list on every add), so that a
    // failure leaves no link without its place in the list.
    if (e.link_ids.size() == e.link_ids.capacity()) e.link_ids.reserve(2 * e.link_ids.size() + 8);
    const Handle id = links_.insert(LinkEntry{navmesh, placed_on_current(e, on_navmesh_grid(link))});
    e.link_ids.push_back(id);
    e.snapshot.reset();
    return id;
}

Handle NavMeshRegistry::add_link(Handle navmesh, const Link& link) {
    std::unique_lock lock(mutex_);
    return insert_link(navmesh, entry(navmesh), link);
}

void NavMeshRegistry::update_link(Handle link, const Link& replacement) {
    std::unique_lock lock(mutex_);
    LinkEntry* found = links_.find(link);
    if (!found) fail_stale("link", link);
    const bool generated = found->link.generated;
    Entry& e = entry(found->navmesh);
    found->link = placed_on_current(e, on_navmesh_grid(replacement));
    found->link.generated = generated;
    e.snapshot.reset();
}

void NavMeshRegistry::remove_link(Handle link) {
    std::unique_lock lock(mutex_);
    const LinkEntry* found = links_.find(link);
    if (!found) fail_stale("link", link);
    Entry& e = entry(found->navmesh);
    e.link_ids.erase(std::find(e.link_ids.begin(), e.link_ids.end(), link));
    links_.erase(link);
    e.snapshot.reset();
}

bool NavMeshRegistry::contains_link(Handle link) const {
    std::shared_lock lock(mutex_);
    return links_.find(link) != nullptr;
}

std::pair<Handle, Link> NavMeshRegistry::link(Handle link) const {
    std::shared_lock lock(mutex_);
    const LinkEntry* found = links_.find(link);
    if (!found) fail_stale("link", link);
    return {found->navmesh, found->link};
}

const std::shared_ptr<const LinkSnapshot>& NavMeshRegistry::snapshot_of(const Entry& e) const {
    // A run of edits with no reader between them costs one copy of the list, not one per edit.
    if (!e.snapshot) {
        auto snapshot = std::make_shared<LinkSnapshot>();
        snapshot->reserve(e.link_ids.size());
        for (Handle id : e.link_ids) snapshot->push_back(StoredLink{id, links_.find(id)->link});
        e.snapshot = std::move(snapshot);
    }
    return e.snapshot;
}

HeldPtr<const LinkSnapshot> NavMeshRegistry::links(Handle navmesh) const {
    {
        std::shared_lock lock(mutex_);
        if (const auto& ready = entry(navmesh).snapshot) return ready;
    }
    // The first reader since an edit builds it, alone: another reader may have built it meanwhile.
    std::unique_lock lock(mutex_);
    return snapshot_of(entry(navmesh));
}

template <typename Goes>
void NavMeshRegistry::erase_links(Entry& e, Goes&& goes) {
    std::vector<Handle> kept;
    kept.reserve(e.link_ids.size());  // nothing below may throw once links are being erased
    for (Handle id : e.link_ids) {
        if (!goes(links_.find(id)->link))
            kept.push_back(id);
        else
            links_.erase(id);
    }
    e.link_ids = std::move(kept);
    e.snapshot.reset();
}

namespace {

bool any_link(const Link&) { return true; }
bool generated(const Link& l) { return l.generated; }
// What a generation of the navmesh's own links replaces: its cross links come from generate_cross_links.
bool generated_within(const Link& l) { return l.generated && !l.crosses(); }

}  // namespace

NavMeshRegistry::SavedTile NavMeshRegistry::saved_tile(Handle navmesh, TileCoord coord) const {
    std::shared_lock lock(mutex_);
    const Entry& e = entry(navmesh);
    SavedTile out;
    for (const auto& t : e.tiles)
        if (t->tiles.tiles.front() == coord) out.tile = t;
    if (!out.tile) fail(ErrorCode::NotFound, "no tile (", coord.x, ", ", coord.z, ") is loaded");
    const TileGrid& grid = e.navmesh->tiles().grid;
    for (Handle id : e.link_ids) {
        const Link& l = links_.find(id)->link;
        if (generated_within(l) && owner_tile(grid, l) == coord) out.links.push_back(l);
    }
    out.made_for = e.made_for;
    out.rides_carrier = e.frame != nullptr;
    return out;
}

void NavMeshRegistry::store_cross_links(Handle navmesh, Handle landing, FunctionRef<bool(const Link&)> replaced,
                                        const std::vector<Link>& links) {
    std::unique_lock lock(mutex_);
    Entry& e = entry(navmesh);
    erase_links(e, [&](const Link& l) { return l.generated && l.landing_navmesh == landing && replaced(l); });
    e.link_ids.reserve(e.link_ids.size() + links.size());
    for (const Link& l : links) insert_link(navmesh, e, l);
}

uint32_t NavMeshRegistry::remove_generated_links(Handle navmesh) {
    std::unique_lock lock(mutex_);
    Entry& e = entry(navmesh);
    const size_t before = e.link_ids.size();
    erase_links(e, generated);
    e.last = LastGeneration{};
    return static_cast<uint32_t>(before - e.link_ids.size());
}

void NavMeshRegistry::replace_links(Handle navmesh, const std::vector<Link>& links, LinkProvenance made_with) {
    std::unique_lock lock(mutex_);
    Entry& e = entry(navmesh);
    erase_links(e, any_link);
    e.link_ids.reserve(links.size());
    for (const Link& l : links) insert_link(navmesh, e, l);
    e.last = LastGeneration{};
    e.made_for.links = std::move(made_with);
}

NavMeshRegistry::Saved NavMeshRegistry::saved(Handle navmesh) const {
    std::unique_lock lock(mutex_);  // alone: the snapshot may need building
    const Entry& e = entry(navmesh);
    return Saved{e.navmesh, snapshot_of(e), e.made_for, e.frame != nullptr};
}

NavMeshProvenance NavMeshRegistry::made_for(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return entry(navmesh).made_for;
}

NavMeshRegistry::GenerationTurn NavMeshRegistry::take_generation_turn(Handle navmesh) {
    std::shared_ptr<std::mutex> turn;
    {
        std::shared_lock lock(mutex_);
        turn = entry(navmesh).generation_turn;
    }
    return GenerationTurn(std::move(turn));
}

LastGeneration NavMeshRegistry::last_generation(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return entry(navmesh).last;
}

void NavMeshRegistry::store_generation(Handle navmesh, LastGeneration last, const std::vector<Link>& generated,
                                       LinkProvenance made_with) {
    std::unique_lock lock(mutex_);
    Entry& e = entry(navmesh);  // a navmesh removed meanwhile keeps nothing
    erase_links(e, generated_within);
    e.link_ids.reserve(e.link_ids.size() + generated.size());
    for (Link l : generated) {
        l.generated = true;
        insert_link(navmesh, e, l);
    }
    e.last = std::move(last);
    e.made_for.links = std::move(made_with);
}

void NavMeshRegistry::replace_tile_links(Handle navmesh, Entry& e, const TileLinks& regenerated) {
    const TileGrid& grid = e.navmesh->tiles().grid;
    erase_links(e, [&](const Link& l) {
        return generated_within(l) && (l.kind == LinkKind::Jump || l.kind == LinkKind::Drop) &&
               std::binary_search(regenerated.owners.begin(), regenerated.owners.end(), owner_tile(grid, l));
    });
    e.link_ids.reserve(e.link_ids.size() + regenerated.links.size());
    for (Link l : regenerated.links) {
        l.generated = true;
        insert_link(navmesh, e, l);
    }
}

bool NavMeshRegistry::store_tile_links(Handle navmesh, const LinkSettings* from, const TileLinks& regenerated) {
    std::unique_lock lock(mutex_);
    Entry* e = navmeshes_.find(navmesh);
    if (!e || e->last.tile_settings.get() != from) return false;
    replace_tile_links(navmesh, *e, regenerated);
    return true;
}

bool NavMeshRegistry::store_update(Handle navmesh, const LinkGeneration* from, const std::vector<Link>& generated) {
    std::unique_lock lock(mutex_);
    Entry* e = navmeshes_.find(navmesh);
    if (!e || e->last.generation.get() != from) return false;
    erase_links(*e, generated_within);
    e->link_ids.reserve(e->link_ids.size() + generated.size());
    for (Link l : generated) {
        l.generated = true;
        insert_link(navmesh, *e, l);
    }
    return true;
}

bool NavMeshRegistry::has_path_graph(Handle navmesh) const {
    std::shared_lock lock(mutex_);
    return entry(navmesh).path_graph != nullptr;
}

HeldPtr<const PathGraph> NavMeshRegistry::path_graph(Handle navmesh) const {
    std::shared_ptr<const NavMesh> mesh;
    std::shared_ptr<const LinkSnapshot> snapshot;
    std::shared_ptr<const CarrierFrame> frame;
    std::shared_ptr<const NavMeshSearchIndex> index;  // the last graph's, when of the same navmesh
    {
        std::shared_lock lock(mutex_);
        const Entry& e = entry(navmesh);
        if (e.snapshot && e.path_graph && e.path_graph->links_ptr() == e.snapshot) return e.path_graph;
        mesh = e.navmesh;
        frame = e.frame;
        snapshot = e.snapshot;
        if (e.path_graph) index = e.path_graph->search_index_ptr();
    }
    if (!snapshot) {
        std::unique_lock lock(mutex_);
        const Entry& e = entry(navmesh);
        snapshot = snapshot_of(e);
        if (e.path_graph && e.path_graph->links_ptr() == snapshot) return e.path_graph;
        // Read again with the snapshot: tiles added or removed meanwhile publish another navmesh.
        mesh = e.navmesh;
        frame = e.frame;
        index = e.path_graph ? e.path_graph->search_index_ptr() : nullptr;
    }
    // Built outside the lock: requests on other navmeshes, and edits, go on meanwhile.
    auto graph = std::make_shared<const PathGraph>(std::move(mesh), snapshot, std::move(frame), std::move(index));
    std::unique_lock lock(mutex_);
    if (const Entry* e = navmeshes_.find(navmesh); e && e->snapshot == snapshot) e->path_graph = graph;
    return graph;
}

}  // namespace nl
