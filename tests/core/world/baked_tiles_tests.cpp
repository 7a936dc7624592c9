// Baked tiles (World::save_tile, World::add_tile_file, tile files in io/navmesh_file): a tile and the
// links it owns to bytes and back. What must hold: the tiles of a full build loaded in any order give
// its navmesh and links bit for bit; a tile's content hash changes with what it was made from and
// with nothing else; a file that is not a good tile of this navmesh changes nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "core_errors.h"
#include "core_world.h"
#include "io/navmesh_file.h"
#include "level_generator.h"

using nl::Vec3;

namespace {

struct Baked {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    nl::Handle navmesh;

    explicit Baked(const nl::levelgen::GeneratedLevel& level, bool links = true) {
        nl::test::add_level(*world, level);
        navmesh = nl::test::build_recast_navmesh(*world, nl::AgentType{}, "{\"tile_size\": 32}");
        if (links) world->generate_links(navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
    }
    std::shared_ptr<const nl::NavMesh> mesh() const { return world->navmeshes().navmesh(navmesh); }
    std::vector<nl::TileCoord> tiles() const { return mesh()->tiles().tiles; }
};

auto key(const nl::Link& l) {
    return std::make_tuple(int(l.kind), l.start.x(), l.start.y(), l.start.z(), l.end.x(), l.end.y(), l.end.z(),
                           l.apex.x(), l.apex.y(), l.apex.z(), l.bidirectional, l.requirements.gap,
                           l.requirements.clearance_width, l.start_polygon, l.end_polygon, l.start_tile, l.end_tile);
}

std::vector<decltype(key(nl::Link{}))> keys(const nl::World& world, nl::Handle navmesh) {
    std::vector<decltype(key(nl::Link{}))> out;
    for (const auto& s : nl::test::links_of(world, navmesh)) out.push_back(key(s.link));
    std::sort(out.begin(), out.end());
    return out;
}

nl::NavMeshFile read(const std::vector<uint8_t>& bytes) { return nl::read_navmesh_file(bytes.data(), bytes.size()); }

}  // namespace

TEST_CASE("tiles saved one by one and loaded in any order give the full build's navmesh and links, bit for bit") {
    const auto level = nl::levelgen::generate_default_level(3);
    Baked full(level);
    REQUIRE(full.tiles().size() >= 9);
    REQUIRE(nl::test::links_of(*full.world, full.navmesh).size() > 10);
    std::vector<std::vector<uint8_t>> files;
    for (const nl::TileCoord& t : full.tiles()) files.push_back(full.world->save_tile(full.navmesh, t));
    std::mt19937 random(7);
    for (int round = 0; round < 3; ++round) {
        std::vector<size_t> order(files.size());
        for (size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::shuffle(order.begin(), order.end(), random);
        auto world = nl::test::make_world(round % 2 + 1);
        nl::test::add_level(*world, level);
        const nl::Handle loaded = world->load_navmesh(read(files[order[0]]));
        for (size_t n = 1; n < order.size(); ++n) world->add_tile_file(loaded, read(files[order[n]]));
        const std::shared_ptr<const nl::NavMesh> back = world->navmeshes().navmesh(loaded);
        CHECK(nl::test::same_navmesh(*back, *full.mesh()));
        CHECK(keys(*world, loaded) == keys(*full.world, full.navmesh));
        for (const auto& s : nl::test::links_of(*world, loaded)) CHECK(s.link.start_polygon != nl::kNoPolygon);
        // Saved again, every tile's file is the one it was loaded from.
        for (size_t i = 0; i < files.size(); ++i) CHECK(world->save_tile(loaded, full.tiles()[i]) == files[i]);
    }
}

TEST_CASE("a tile out and back from its file: its links go with it and come back; links into it wait parked") {
    Baked b(nl::levelgen::generate_default_level(3));
    const auto before = keys(*b.world, b.navmesh);
    for (const nl::TileCoord& t : b.tiles()) {
        const std::vector<uint8_t> file = b.world->save_tile(b.navmesh, t);
        b.world->remove_tile(b.navmesh, t);
        for (const auto& s : nl::test::links_of(*b.world, b.navmesh)) {
            CHECK(s.link.start_tile != t);  // its own went with it
            CHECK((s.link.end_polygon == nl::kNoPolygon) == (s.link.end_tile == t));
        }
        b.world->add_tile_file(b.navmesh, read(file));
        CHECK(keys(*b.world, b.navmesh) == before);
    }
}

TEST_CASE("a tile's content hash changes with what it was made from, and with nothing else") {
    // Platforms in a row 100 m long over a floor.
    nl::levelgen::GeneratedLevel level;
    for (int k = 0; k < 8; ++k)
        level.add_box(nl::levelgen::Box{{k * 12.0f, -1.0f, 0.0f}, {k * 12.0f + 9.0f, 0.0f, 6.0f}});
    level.add_box(nl::levelgen::Box{{-4.0f, -5.0f, -4.0f}, {100.0f, -4.0f, 10.0f}});
    Baked a(level);
    std::vector<uint64_t> hashes;
    for (const nl::TileCoord& t : a.tiles()) hashes.push_back(a.world->tile_content_hash(a.navmesh, t));
    // The same level, built and generated again: the same hashes, and they differ between tiles.
    Baked same(level);
    for (size_t i = 0; i < hashes.size(); ++i)
        CHECK(same.world->tile_content_hash(same.navmesh, a.tiles()[i]) == hashes[i]);
    CHECK(std::set<uint64_t>(hashes.begin(), hashes.end()).size() == hashes.size());
    // A box under one corner of the level: the tiles within reach of it hash differently, the others as
    // before (the grid starts where the level does in x and z: the box keeps to them).
    const nl::Aabb bounds = a.mesh()->bounds();
    level.add_box(nl::levelgen::Box{{bounds.min.x() + 0.5f, bounds.min.y() - 3.0f, bounds.min.z() + 0.5f},
                                    {bounds.min.x() + 1.0f, bounds.min.y() - 2.0f, bounds.min.z() + 1.0f}});
    Baked edited(level);
    REQUIRE(edited.tiles() == a.tiles());
    size_t changed = 0;
    for (size_t i = 0; i < hashes.size(); ++i)
        changed += edited.world->tile_content_hash(edited.navmesh, a.tiles()[i]) != hashes[i];
    CHECK(changed > 0);
    CHECK(changed < hashes.size());
    // Other link settings: every tile's hash changes.
    nl::LinkSettings wider;
    wider.max_jump_gap = 5.0f;
    same.world->generate_links(same.navmesh, wider, {}, nl::test::keep_going);
    for (size_t i = 0; i < hashes.size(); ++i)
        CHECK(same.world->tile_content_hash(same.navmesh, a.tiles()[i]) != hashes[i]);
}

TEST_CASE("a file that is not a good tile of the navmesh is refused and changes nothing") {
    Baked b(nl::levelgen::generate_default_level(3));
    const auto links = keys(*b.world, b.navmesh);
    const auto mesh = b.mesh();
    const nl::TileCoord first = b.tiles().front();
    const std::vector<uint8_t> file = b.world->save_tile(b.navmesh, first);
    auto unchanged = [&] {
        CHECK(b.mesh() == mesh);
        CHECK(keys(*b.world, b.navmesh) == links);
    };
    // Loaded already.
    CHECK_THROWS_WITH_AS(b.world->add_tile_file(b.navmesh, read(file)), doctest::Contains("loaded already"), nl::Error);
    unchanged();
    // Every truncation and a flipped byte: the reader refuses.
    for (size_t size = 0; size < file.size(); size += std::max<size_t>(1, file.size() / 97))
        CHECK_THROWS_AS(nl::read_navmesh_file(file.data(), size), nl::Error);
    std::vector<uint8_t> flipped = file;
    flipped[flipped.size() / 2] ^= 0x10;
    CHECK_THROWS_AS(nl::read_navmesh_file(flipped.data(), flipped.size()), nl::Error);
    // A link owned by another tile (tile_links.h): it would load with this tile and be lost saving it.
    {
        nl::NavMeshRegistry::SavedTile saved;
        for (const nl::TileCoord& at : b.tiles())
            if (saved = b.world->navmeshes().saved_tile(b.navmesh, at); !saved.links.empty()) break;
        REQUIRE(!saved.links.empty());
        const nl::TileCoord owner = *saved.links.front().start_tile;
        saved.links.front().start_tile = nl::TileCoord{owner.x + 1, owner.z};
        const std::vector<uint8_t> stray = nl::write_tile_file(*saved.tile, saved.links, saved.made_for, 0);
        CHECK_THROWS_WITH_AS(read(stray), doctest::Contains("link 0 starts on tile"), nl::Error);
    }
    // A whole navmesh's file.
    const nl::NavMeshRegistry::Saved whole = b.world->navmeshes().saved(b.navmesh);
    const std::vector<uint8_t> solo = nl::write_navmesh_file(*whole.navmesh, {}, whole.made_for, false);
    CHECK_THROWS_WITH_AS(b.world->add_tile_file(b.navmesh, read(solo)), doctest::Contains("not a tile"), nl::Error);
    // A tile made with other settings (links never generated).
    b.world->remove_tile(b.navmesh, first);
    const auto without = b.mesh();
    const auto links_without = keys(*b.world, b.navmesh);
    Baked plain(nl::levelgen::generate_default_level(3), false);
    CHECK_THROWS_WITH_AS(b.world->add_tile_file(b.navmesh, read(plain.world->save_tile(plain.navmesh, first))),
                         doctest::Contains("link settings"), nl::Error);
    CHECK(b.mesh() == without);
    CHECK(keys(*b.world, b.navmesh) == links_without);
    b.world->add_tile_file(b.navmesh, read(file));
    CHECK(keys(*b.world, b.navmesh) == links);
}
