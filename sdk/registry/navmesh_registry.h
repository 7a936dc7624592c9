// The navmeshes of a world, each with everything that belongs to it: its links (manual and
// generated, and the snapshot readers take), its last link generation (what an update in a box
// continues) and the path graph searches read.
//
// Locking: one reader-writer lock guards all of it, for every navmesh, so removing a navmesh (with
// its links, generation and graph) is one step no reader sees half of. Readers (snapshots, graphs,
// lookups) share it; edits take it alone, and only for bookkeeping: the work that takes time (a link
// generation, building a path graph) runs outside it, on data the lock handed out, and its result is
// stored under the lock if the navmesh is still there. The lock is never held while the host or a
// plugin is called. Separately, each navmesh has a generation turn: its generations and updates run
// one at a time (see GenerationTurn).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "links/link_generation.h"
#include "links/link_snapshot.h"
#include "navmesh/provenance.h"
#include "navmesh/navmesh.h"
#include "navmesh/tile_join.h"
#include "navmesh/carrier_pose.h"
#include "path/path_graph.h"
#include "util/function_ref.h"
#include "util/handle.h"
#include "util/held_ptr.h"
#include "os/shared_mutex.h"
#include "io/plugin_settings.h"

namespace nl {

// A navmesh's last generation and what it ran with: what nl_navmesh_update_links_in_box continues.
struct LastGeneration {
    std::shared_ptr<LinkGeneration> generation;  // null: none, or forgotten since
    PluginSettings plugin_settings;
    // A tiled navmesh's generation (generation is null): what the links of the tiles that arrive, and
    // of the tiles within reach of them, are generated with (tile_links.h).
    std::shared_ptr<const LinkSettings> tile_settings;
};

// Generated jumps and drops of a tiled navmesh, by the tiles that own them (tile_links.h): `links`
// replaces the generated jumps and drops those tiles own.
struct TileLinks {
    std::vector<TileCoord> owners;  // in row order
    std::vector<Link> links;
};

class NavMeshRegistry {
public:
    explicit NavMeshRegistry(uint32_t handle_tag)
        : navmeshes_(handle_tag, HandleKind::NavMesh), links_(handle_tag, HandleKind::Link) {}

    // Navmeshes. Lookups throw InvalidHandle for a null, removed or foreign handle.
    // `carrier`: the movable mesh the navmesh rides (null: none), the navmesh in its space, placed at
    // `to_world` now; navmeshes on one mesh share its frame.
    // `tiles`: for a tiled navmesh, the tiles it was joined from (tile_join.h).
    Handle add(std::shared_ptr<const NavMesh> navmesh, Handle carrier = Handle{},
               const Transform& to_world = Transform::Identity(), NavMeshProvenance made_for = {},
               TileInputs tiles = {});
    // Removes the navmesh, its links, its last generation and its path graph together, and the cross
    // links of other navmeshes that land on it. Readers that
    // hold its navmesh, a snapshot or a graph keep them; a generation that finishes later keeps nothing.
    void remove(Handle navmesh);
    bool contains(Handle navmesh) const;
    HeldPtr<const NavMesh> navmesh(Handle navmesh) const;
    std::vector<Handle> handles() const;
    // The frame of the mesh the navmesh rides; null for one that rides nothing.
    HeldPtr<const CarrierFrame> frame(Handle navmesh) const;
    // Both at once (one lock: queries that read a navmesh where it stands now).
    struct Placed {
        std::shared_ptr<const NavMesh> navmesh;
        std::shared_ptr<const CarrierFrame> frame;
    };
    Placed placed(Handle navmesh) const;
    // Whether any navmesh rides `mesh`.
    bool carried_by(Handle mesh) const;
    // The first navmesh (in the order added) that rides `mesh` and was made for `body` (same_body);
    // null when none does.
    Handle riding(Handle mesh, const AgentType& body) const;
    // Places the navmeshes that ride `mesh` (if any) at `to_world`; nothing else changes.
    void move_carrier(Handle mesh, const Transform& to_world);

    // Tiles of a tiled navmesh: those it was joined from (empty for a solo navmesh).
    TileInputs tile_inputs(Handle navmesh) const;
    // Publishes `joined`, the navmesh joined from `tiles`, in the navmesh's place, as one step: every
    // link with an end is placed on it again, those with an end on a tile it lacks (or off it) parked,
    // out of every path, until a later navmesh holds both ends; the cross links of other navmeshes
    // that land on it likewise; `regenerated` (if any) replaces the generated links of its tiles. A
    // tiled generation (LastGeneration::tile_settings) is kept, any other forgotten (an update in a box
    // needs a new generation). Readers holding the old navmesh, a snapshot or a graph keep them. Call it
    // under the navmesh's generation turn, with `tiles` made from what tile_inputs gave under that turn.
    void replace_tiles(Handle navmesh, TileInputs tiles, std::shared_ptr<const NavMesh> joined,
                       const TileLinks* regenerated = nullptr);

    // Links. Each edit publishes: the next snapshot reader sees it.
    Handle add_link(Handle navmesh, const Link& link);
    // Replaces a link's fields; its navmesh and whether it was generated stay.
    void update_link(Handle link, const Link& replacement);
    void remove_link(Handle link);
    bool contains_link(Handle link) const;
    // The link and the navmesh it belongs to.
    std::pair<Handle, Link> link(Handle link) const;
    HeldPtr<const LinkSnapshot> links(Handle navmesh) const;
    // Removes the generated links; manual ones stay. The last generation is forgotten with them.
    uint32_t remove_generated_links(Handle navmesh);
    // Replaces every link (a links file, made with `made_with`); the last generation is forgotten.
    void replace_links(Handle navmesh, const std::vector<Link>& links, LinkProvenance made_with);
    // What the navmesh and its generated links were made for and with.
    NavMeshProvenance made_for(Handle navmesh) const;
    // The navmesh, its links and what they were made with, read together (a baked file of one moment:
    // a generation finishing meanwhile is in all of it or in none).
    struct Saved {
        std::shared_ptr<const NavMesh> navmesh;
        std::shared_ptr<const LinkSnapshot> links;
        NavMeshProvenance made_for;
        bool rides_carrier = false;
    };
    Saved saved(Handle navmesh) const;
    // One tile of a tiled navmesh and the generated links it owns (tile_links.h), read together.
    // Throws NotFound when no tile is loaded at `coord`.
    struct SavedTile {
        std::shared_ptr<const NavMeshInput> tile;
        std::vector<Link> links;
        NavMeshProvenance made_for;
        bool rides_carrier = false;
    };
    SavedTile saved_tile(Handle navmesh, TileCoord coord) const;

    // Generations and updates of one navmesh run one at a time, from reading its last generation to
    // storing its links, so a later one never loses to an earlier one: hold a turn for that span. A
    // thread holds one turn at a time: asking for a second (from a progress callback or a plugin of
    // the generation it runs) throws InvalidArgument instead of waiting, because two threads each
    // waiting for the other's navmesh from inside their callbacks would never wake.
    //
    // GenerationOnThisThread marks the calling thread as running a generation (a navmesh's own links or
    // cross links) for as long as it lives, and throws InvalidArgument if it already is: a generation
    // called from another's progress callback or plugin is refused, whichever kinds they are.
    class GenerationOnThisThread {
    public:
        GenerationOnThisThread();
        ~GenerationOnThisThread();
        GenerationOnThisThread(const GenerationOnThisThread&) = delete;
        GenerationOnThisThread& operator=(const GenerationOnThisThread&) = delete;
    };
    class GenerationTurn {
    public:
        explicit GenerationTurn(std::shared_ptr<std::mutex> turn);
        ~GenerationTurn();
        GenerationTurn(const GenerationTurn&) = delete;
        GenerationTurn& operator=(const GenerationTurn&) = delete;

    private:
        GenerationOnThisThread one_per_thread_;
        std::shared_ptr<std::mutex> turn_;
    };
    GenerationTurn take_generation_turn(Handle navmesh);

    LastGeneration last_generation(Handle navmesh) const;
    // A generation's result: its links replace the generated ones and it becomes the last generation
    // (made with `made_with`).
    void store_generation(Handle navmesh, LastGeneration last, const std::vector<Link>& generated,
                          LinkProvenance made_with);
    // An update's result: stored only while `from` is still the navmesh's last generation (not
    // forgotten by a removal or a load meanwhile); returns whether it was.
    bool store_update(Handle navmesh, const LinkGeneration* from, const std::vector<Link>& generated);
    // A tiled update's result (the tiles' links again): stored only while `from` is still the
    // navmesh's tiled generation's settings; returns whether it was.
    bool store_tile_links(Handle navmesh, const LinkSettings* from, const TileLinks& regenerated);

    // Replaces the generated cross links from `navmesh` to `landing` that `replaced` picks with
    // `links` (generated cross links from one to the other); every other link stays. Throws
    // InvalidHandle for `navmesh`.
    void store_cross_links(Handle navmesh, Handle landing, FunctionRef<bool(const Link&)> replaced,
                           const std::vector<Link>& links);

    // The graph searches read: the navmesh and its links as they are now, built once per snapshot.
    HeldPtr<const PathGraph> path_graph(Handle navmesh) const;
    // Whether a graph was built for the navmesh since it was added (paths were asked for on it),
    // whatever snapshot it was built for. Throws InvalidHandle.
    bool has_path_graph(Handle navmesh) const;

private:
    struct Entry {
        std::shared_ptr<const NavMesh> navmesh;
        std::shared_ptr<CarrierFrame> frame;                   // null: rides nothing
        std::vector<Handle> link_ids;                          // in the order they were added
        mutable std::shared_ptr<const LinkSnapshot> snapshot;  // null after an edit, until read
        mutable std::shared_ptr<const PathGraph> path_graph;   // for some snapshot; checked on read
        LastGeneration last;
        NavMeshProvenance made_for;
        std::shared_ptr<std::mutex> generation_turn = std::make_shared<std::mutex>();
        TileInputs tiles;  // a tiled navmesh's, in row order
    };
    struct LinkEntry {
        Handle navmesh;
        Link link;
    };

    Entry& entry(Handle navmesh);
    // The frame of `mesh` if a navmesh rides it; null otherwise. Needs the lock.
    std::shared_ptr<CarrierFrame> frame_of_mesh(Handle mesh) const;
    const Entry& entry(Handle navmesh) const;
    // Builds the entry's snapshot if an edit made it stale; needs the lock held alone.
    const std::shared_ptr<const LinkSnapshot>& snapshot_of(const Entry& e) const;
    // Erases the entry's links that `goes` says go (by the link), keeping the order of the rest.
    template <typename Goes>
    void erase_links(Entry& e, Goes&& goes);
    Handle insert_link(Handle navmesh, Entry& e, const Link& link);
    // Replaces the generated jumps and drops of the tiles `regenerated` names; needs the lock alone.
    void replace_tile_links(Handle navmesh, Entry& e, const TileLinks& regenerated);
    // The link with its ends placed on the navmeshes as they are now (where tiles may have changed
    // since its writer placed it). Needs the lock.
    Link placed_on_current(const Entry& e, Link link) const;

    mutable SharedMutex mutex_{"the navmeshes"};
    SlotMap<Entry> navmeshes_;
    SlotMap<LinkEntry> links_;
};

}  // namespace nl
