"""The Python binding's test: the same scenario as the C# and Rust tests, through navlink.py.

Environment: NAVLINK_LIBRARY (libnavlink.so to test), NAVLINK_LEVELS_DIR (the shared levels, default
../shared/levels beside the source tree), NAVLINK_INCLUDE_DIRS (PATH-style list of the header folders, for
the layout check; default: the source tree's and build/capi/include).
"""
import array
import ast
import asyncio
import ctypes
import ctypes.util
import enum
import gc
import json
import math
import os
import subprocess
import sys
import tempfile
import threading
import time
import typing
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "layout"))

import c_layout  # noqa: E402  (bindings/layout/c_layout.py)
import navlink as nl  # noqa: E402

LEVELS = os.environ.get("NAVLINK_LEVELS_DIR") or os.path.join(SOURCE_ROOT, "..", "shared", "levels")
INCLUDE_DIRS = (os.environ["NAVLINK_INCLUDE_DIRS"].split(os.pathsep) if os.environ.get("NAVLINK_INCLUDE_DIRS") else
                [os.path.join(SOURCE_ROOT, "capi", "include"), os.path.join(SOURCE_ROOT, "plugins", "include"),
                 os.path.join(SOURCE_ROOT, "build", "capi", "include")])

BOX_INDICES = [0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6]
FLOOR = [-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5]
QUAD = [0, 2, 1, 0, 3, 2]
WEST, EAST = (-6.0, 0.0, 0.0), (6.0, 0.0, 0.0)
# A flat floor in tiles (tests/core/world/tile_streaming_tests.cpp's corridor, shorter): a 40 x 1 x 12 m box, top
# y = 0, and two points near its ends.
TILED_FLOOR_LO, TILED_FLOOR_HI = (0, -1, 0), (40, 0, 12)
WEST_OF_TILED_FLOOR, EAST_OF_TILED_FLOOR = (2, 0, 3), (38, 0, 3)
# The moving surface: an 8 x 4 m movable box (top y = 0 in its own space) carrying a 7.2 x 3.2 m navmesh quad,
# then moved 10 m along x and turned 90 degrees about y: its x axis goes to the world's -z, its z axis to x.
RAFT_LO, RAFT_HI = (-4, -1, -2), (4, 0, 2)
RAFT_QUAD = [-3.6, 0, -1.6, -3.6, 0, 1.6, 3.6, 0, 1.6, 3.6, 0, -1.6]
RAFT_MOVED = [0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 10, 0, 0, 1]  # column-major
RAFT_SCALED = [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 10, 0, 0, 1]
# A cross link onto a moving surface: a static 6 x 4 m ledge navmesh (x in [-6, 0], z in [-2, 2], y = 0) and,
# 1 m past its edge, a 4 x 4 m movable box (x in [1, 5]; its own space is the world's until it moves) carrying
# a 3.6 x 3.6 m navmesh quad. The link goes from the ledge's edge onto the box; the box then moves 2 m away
# along x and back.
LEDGE_QUAD = [-6, 0, -2, -6, 0, 2, 0, 0, 2, 0, 0, -2]
DECK_LO, DECK_HI = (1, -1, -2), (5, 0, 2)
DECK_QUAD = [1.2, 0, -1.8, 1.2, 0, 1.8, 4.8, 0, 1.8, 4.8, 0, -1.8]
DECK_HOME = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
DECK_AWAY = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1]  # 2 m along x
CROSS_START, CROSS_END, CROSS_END_AWAY = (-0.4, 0, 0), (1.6, 0, 0), (3.6, 0, 0)
# Generated cross links (tests/core/world/surface_tests.cpp's ferry): a static 6 x 6 m ledge (box x in [0, 6], z in
# [0, 6], top y = 0) whose navmesh is its top eroded 0.3 m, and a 4 x 4 m movable box (top y = 0 in its own
# space, centred on its origin) carrying its top eroded 0.3 m as a navmesh, placed 1 m off the ledge's edge
# (centre x = 9, z = 3), then 3 m off (x = 11). Both navmeshes for radius 0.3; jumps up to 2 m across.
LEDGE_BOX_LO, LEDGE_BOX_HI = (0, -1, 0), (6, 0, 6)
LEDGE_TOP = [0.3, 0, 0.3, 0.3, 0, 5.7, 5.7, 0, 5.7, 5.7, 0, 0.3]
PLATFORM_LO, PLATFORM_HI = (-2, -0.5, -2), (2, 0, 2)
PLATFORM_TOP = [-1.7, 0, -1.7, -1.7, 0, 1.7, 1.7, 0, 1.7, 1.7, 0, -1.7]

# A ferry (tests/core/world/surface_tests.cpp's): two 6 x 6 m ledges (boxes x in [0, 6] and [16, 22], z in [0, 6], tops
# y = 0) with one static navmesh of their tops eroded 0.3 m (one quad each), and the platform's box as a shuttle
# carrying PLATFORM_TOP, on a timetable: docked at the near ledge (centre x = 8) for 3 s, 4 s across, docked at
# the far one (x = 14) for 3 s, 4 s back.
FERRY_NEAR_LO, FERRY_NEAR_HI = (0, -1, 0), (6, 0, 6)
FERRY_FAR_LO, FERRY_FAR_HI = (16, -1, 0), (22, 0, 6)
FERRY_LEDGES = [0.3, 0, 0.3, 0.3, 0, 5.7, 5.7, 0, 5.7, 5.7, 0, 0.3,
                16.3, 0, 0.3, 16.3, 0, 5.7, 21.7, 0, 5.7, 21.7, 0, 0.3]
FERRY_NEAR_DOCK, FERRY_FAR_DOCK = 8.0, 14.0
FERRY_GOAL = (20, 0, 3)


def ferry_x(t):
    """The shuttle's centre x at time t of its 14 s timetable."""
    u = math.fmod(t, 14.0)
    if u < 3:
        return FERRY_NEAR_DOCK
    if u < 7:
        return FERRY_NEAR_DOCK + (FERRY_FAR_DOCK - FERRY_NEAR_DOCK) * (u - 3) / 4
    if u < 10:
        return FERRY_FAR_DOCK
    return FERRY_FAR_DOCK - (FERRY_FAR_DOCK - FERRY_NEAR_DOCK) * (u - 10) / 4


def platform_at(x):
    """The platform's transform: its centre at (x, 0, 3) (column-major)."""
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 3, 1]


def box_vertices(lo, hi):
    """A box's corners, flat x y z: corner k takes x from bit 0, y from bit 1, z from bit 2."""
    v = []
    for k in range(8):
        v += [hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2]]
    return v


def add_box(world, lo, hi, flags=0, transform=None):
    return world.add_mesh(box_vertices(lo, hi), BOX_INDICES, flags=flags, transform=transform)


def add_gap_level(world):
    """Two 10 x 10 m platforms 2 m apart over a 20 m pit: only a jumper crosses (3.2-3.8 m between navmesh rims)."""
    add_box(world, (-11, -1, -5), (-1, 0, 5))
    add_box(world, (1, -1, -5), (11, 0, 5))
    add_box(world, (-12, -21, -6), (12, -20, 6))


def add_bridge_level(world):
    """tests/abi/agents_tests.c's level: two 4 x 10 m platforms (tops at y = 0) 2 m apart along x, x in [0, 4]
    and [6, 10], z in [0, 10], joined by a bridge at z 8-10; the host's navmesh is their tops set in 0.3 m
    from every rim (five convex polygons, for radius 0.3), its links generated. A walker goes round by the
    bridge; a jumper jumps the gap."""
    add_box(world, (0, -1, 0), (4, 0, 10))
    add_box(world, (6, -1, 0), (10, 0, 10))
    add_box(world, (4, -1, 8), (6, 0, 10))
    vertices, indices, corner_counts = bridge_navmesh_polygons()
    navmesh = world.add_navmesh(vertices, indices, corner_counts, agent_type=bridge_agent_type())
    world.generate_links(navmesh)
    return navmesh


def bridge_navmesh_polygons():
    """The bridge level's navmesh as lists: (vertices, indices, corners of each polygon)."""
    polygons = [[(0.3, 0.3), (0.3, 8), (3.7, 8), (3.7, 0.3)],
                [(0.3, 8), (0.3, 9.7), (4, 9.7), (4, 8), (3.7, 8)],
                [(4, 8), (4, 9.7), (6, 9.7), (6, 8)],
                [(6, 8), (6, 9.7), (9.7, 9.7), (9.7, 8), (6.3, 8)],
                [(6.3, 0.3), (6.3, 8), (9.7, 8), (9.7, 0.3)]]
    vertices = [c for polygon in polygons for x, z in polygon for c in (x, 0, z)]
    return vertices, list(range(len(vertices) // 3)), [len(p) for p in polygons]


def bridge_agent_type():
    agent = nl.default_agent_type()
    agent.radius = 0.3
    return agent


def walker():
    return nl.default_agent_capabilities()


def jumper(distance=4.5):
    c = nl.default_agent_capabilities()
    c.max_jump_distance, c.max_jump_height, c.max_drop_height = distance, 1.5, 5.0
    return c


def horizontal(a, b):
    return math.hypot(a[0] - b[0], a[2] - b[2])


def distance(a, b):
    return math.sqrt(sum((a[i] - b[i]) ** 2 for i in range(3)))


def gap_level_with_links(world):
    add_gap_level(world)
    navmesh = world.build_navmesh()
    world.generate_links(navmesh)
    return navmesh


class NavLinkTestCase(unittest.TestCase):
    def assertFails(self, bit, part, call, *args, **kwargs):
        with self.assertRaises(nl.NavLinkError) as caught:
            call(*args, **kwargs)
        e = caught.exception
        self.assertTrue(e.has(nl.STATUS_FAILURE) and e.has(bit), "status %#x lacks %#x: %s" % (e.status, bit, e))
        self.assertIn(part, e.message)

    def assertNear(self, got, want, msg=None):
        # Within a millimetre: navmeshes keep coordinates on a grid of 1/1024 m.
        for g, w in zip(got, want):
            self.assertAlmostEqual(g, w, delta=1e-3, msg="%s: %s, expected %s" % (msg, list(got), list(want)))

    def assertJumperAcross(self, world, r):
        """Walk to the west rim, one generated jump (apex above), walk to the goal."""
        self.assertEqual(r.outcome, nl.PATH_COMPLETE)
        p = r.points
        jumps = [i for i, q in enumerate(p) if q.segment != nl.SEGMENT_WALK]
        self.assertEqual(len(jumps), 1)
        j = jumps[0]
        self.assertEqual((p[j].segment, r.info.links_used), (nl.LINK_JUMP, 1))
        self.assertTrue(p[j].position[0] < -1 and p[j + 1].position[0] > 1, "west rim to east rim")
        link = world.link(p[j].link)
        self.assertTrue(link.kind == nl.LINK_JUMP and link.generated == 1)
        self.assertGreater(p[j].apex[1], max(p[j].position[1], p[j + 1].position[1]))
        self.assertTrue(p[-1].segment == nl.SEGMENT_WALK and p[0].link.is_null)
        self.assertLess(horizontal(p[0].position, WEST), 0.01)
        self.assertLess(horizontal(p[-1].position, EAST), 0.01)
        self.assertTrue(12 <= r.info.length < 13, r.info.length)

    def assertWalkerStopsAtGap(self, r):
        self.assertEqual(r.outcome, nl.PATH_PARTIAL)
        self.assertEqual(r.info.links_used, 0)
        self.assertTrue(all(q.segment == nl.SEGMENT_WALK and q.link.is_null for q in r.points))
        self.assertTrue(len(r.points) >= 2 and all(q.position[0] < -1 for q in r.points), "stays west")
        self.assertGreater(r.points[-1].position[0], -2.1, "ends at the west rim")


class LayoutTest(unittest.TestCase):
    def test_structs_match_the_c_compiler(self):
        lines = c_layout.layout_lines(INCLUDE_DIRS).splitlines()
        structs = [line.split() for line in lines if line.startswith("struct ")]
        self.assertGreaterEqual(len(structs), 30)
        self.assertEqual({s[1] for s in structs}, set(nl.C_STRUCTS), "every C struct has a ctypes class")
        for _, name, size, _ in structs:
            self.assertEqual(ctypes.sizeof(nl.C_STRUCTS[name]), int(size), name)
        fields = {}
        for line in lines:
            if line.startswith("field "):
                _, struct, field, offset, size = line.split()
                fields.setdefault(struct, []).append(field)
                member = getattr(nl.C_STRUCTS[struct], field)
                self.assertEqual((member.offset, member.size), (int(offset), int(size)), struct + "." + field)
        for struct, names in fields.items():
            self.assertEqual([f[0] for f in nl.C_STRUCTS[struct]._fields_], names, struct)

    def test_initialisers_match_the_header(self):
        """Each NL_DEFINE_OUTPUT_INIT of the headers has its twin here: same name, its struct's class, the
        size the C one sets, every other byte zero; and that class's constructor does the same."""
        lines = c_layout.layout_lines(INCLUDE_DIRS).splitlines()
        inits = [line.split()[1:] for line in lines if line.startswith("init ")]
        self.assertGreaterEqual(len(inits), 11)
        for struct, function, size in inits:
            cls = nl.C_STRUCTS[struct]
            for value in (getattr(nl, function)(), cls()):
                self.assertIs(type(value), cls, function)
                self.assertEqual(value.size, int(size), function)
                self.assertEqual(bytes(value)[4:], bytes(ctypes.sizeof(cls) - 4), function)
        growable = {name for name, cls in nl.C_STRUCTS.items() if issubclass(cls, nl._Growable)}
        self.assertEqual(growable, {struct for struct, _, _ in inits}, "the classes that set size are the initialised ones")

    def test_constants_match_the_header(self):
        """Every integer #define NL_X of the headers is navlink.X with its value, and every integer
        constant of the module is one of them."""
        lines = c_layout.layout_lines(INCLUDE_DIRS).splitlines()
        header = {name[len("NL_"):]: int(value) for _, name, value in
                  (line.split() for line in lines if line.startswith("const "))}
        self.assertGreaterEqual(len(header), 40)
        for name, value in header.items():
            self.assertEqual(getattr(nl, name, None), value, "NL_" + name)
        module = {name for name, value in vars(nl).items()
                  if name.isupper() and type(value) is int}
        self.assertEqual(module - set(header), set(), "constants the header does not define")


class LevelTest(NavLinkTestCase):
    def test_version_and_statuses(self):
        self.assertEqual(nl.version(), (nl.VERSION_MAJOR, nl.VERSION_MINOR, nl.VERSION_PATCH))
        self.assertIn("invalid handle", nl.status_string(nl.STATUS_FAILURE | nl.STATUS_INVALID_HANDLE))

    def test_world_options(self):
        with nl.World(worker_count=1, path_worker_count=0) as one:
            self.assertEqual(one.worker_count, 1)
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "worker_count", nl.World, worker_count=-5)
        world = nl.World()
        world.close()
        self.assertRaises(ValueError, world.meshes)

    def test_host_task_system(self):
        """An inline host (each task run at once, in pieces of min_range; no handle to finish) gives the same
        rays and links as NavLink's own threads, and is really called."""
        calls = {"enqueue": 0, "finish": 0}

        def enqueue(user, task, task_context, item_count, min_range):
            calls["enqueue"] += 1
            for begin in range(0, item_count, max(1, min_range)):
                task(task_context, begin, min(item_count, begin + max(1, min_range)), 0)
            return None

        def finish(user, handle):
            calls["finish"] += 1

        rays = [nl.Ray(nl.Vec3(-13 + 0.45 * x, 5, -6 + 0.3 * z), nl.Vec3(0, -1, 0), 100)
                for x in range(60) for z in range(40)]

        def run(world):
            navmesh = gap_level_with_links(world)
            hits = [(h.hit, h.distance) for h in world.cast_rays(rays)]
            links = [(l.kind, tuple(l.start), tuple(l.end), tuple(l.apex), l.requirements.gap)
                     for l in world.links(navmesh)]
            return hits, links

        with nl.World(worker_count=2, path_worker_count=0) as world:
            reference = run(world)
        self.assertTrue(reference[1], "the gap level has jumps")
        with nl.World(worker_count=1, path_worker_count=0, task_enqueue_fn=enqueue, task_finish_fn=finish) as world:
            self.assertEqual(world.worker_count, 1)
            self.assertEqual(run(world), reference)
        self.assertGreater(calls["enqueue"], 0)
        self.assertEqual(calls["finish"], 0)
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "task_finish_fn", nl.World, worker_count=1, task_enqueue_fn=enqueue)
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "worker_count", nl.World, task_enqueue_fn=enqueue,
                         task_finish_fn=finish)

    def test_meshes_and_rays(self):
        with nl.World() as world:
            floor = world.add_mesh(FLOOR, QUAD, user_data=42)
            self.assertTrue(world.is_mesh_valid(floor))
            info = world.mesh_info(floor)
            self.assertEqual((info.triangle_count, info.vertex_count, info.user_data), (2, 4, 42))
            hits = world.cast_rays([nl.Ray(nl.Vec3(-2, 2, 1), nl.Vec3(0, -1, 0), 100),
                                    nl.Ray(nl.Vec3(8, 2, 0), nl.Vec3(0, -1, 0), 100)])
            self.assertTrue(hits[0].hit == 1 and hits[0].mesh == floor)
            self.assertAlmostEqual(hits[0].distance, 2, places=5)
            self.assertAlmostEqual(hits[0].normal[1], 1, places=5)
            self.assertTrue(hits[1].hit == 0 and hits[1].distance == 0)

            at = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 1, 0, 1]
            lift = world.add_mesh([-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1], QUAD, flags=nl.MESH_MOVABLE, transform=at)
            down = [nl.Ray(nl.Vec3(4, 50, 0), nl.Vec3(0, -1, 0), 100)]
            self.assertAlmostEqual(world.cast_rays(down)[0].point[1], 1, places=4)
            at[13] = 3.5
            world.set_mesh_transform(lift, at)
            self.assertAlmostEqual(world.cast_rays(down)[0].point[1], 3.5, places=4)
            self.assertEqual(len(world.meshes()), 2)
            self.assertEqual(world.segments_blocked([((4, 5, 0), (4, 2, 0)), ((-4, 5, 0), (-4, 2, 0))]), [True, False])

            world.remove_mesh(lift)
            self.assertFalse(world.is_mesh_valid(lift))
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_mesh_remove", world.remove_mesh, lift)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_mesh_set_transform", world.set_mesh_transform, lift, at)

    def test_invalid_input_and_the_log_callback(self):
        logged = []
        with nl.World(log=lambda level, status, message: logged.append(message)) as world:
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "indices", world.add_mesh, FLOOR, [0, 1, 7])
            self.assertTrue(len(logged) == 1 and "indices" in logged[0], logged)
            zero = nl.Ray(nl.Vec3(0, 1, 0), nl.Vec3(0, 0, 0), 1)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "rays", world.cast_rays, [zero])
            self.assertFails(nl.STATUS_PARSE_ERROR, ":2:", world.add_obj_memory, b"v 0 0 0\nf 1 2 9\n")
            self.assertFails(nl.STATUS_NOT_FOUND, "nl_mesh_add_obj_file", world.add_obj_file, "/no/such/level.obj")
            floor = world.add_mesh(FLOOR, QUAD)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "transform", world.set_mesh_transform, floor, [0] * 16)
            # Null pointers through `lib`: INVALID_ARGUMENT, the argument named.
            status = nl.lib.nl_world_get_meshes(world.pointer, None, 0, None)
            self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT)
            self.assertIn("out_count", nl.last_error_message())
            count = ctypes.c_uint32()
            self.assertEqual(nl.lib.nl_world_get_meshes(world.pointer, None, 0, ctypes.byref(count)), nl.STATUS_SUCCESS)
            self.assertEqual(nl.last_error_message(), "")
            # Output arrays of growable elements: the library reads the element size from the first element
            # (a ctypes array is zeroed: World's methods set it, a raw caller must).
            ray = nl.Ray(nl.Vec3(0, 2, 0), nl.Vec3(0, -1, 0), 100)
            hits = (nl.RayHit * 2)()
            status = nl.lib.nl_world_cast_rays(world.pointer, ctypes.byref(ray), 1, hits)
            self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT)
            self.assertIn("out_hits", nl.last_error_message())
            hits[0] = nl.nl_ray_hit_init()
            self.assertEqual(nl.lib.nl_world_cast_rays(world.pointer, ctypes.byref(ray), 1, hits), nl.STATUS_SUCCESS)
            self.assertEqual((hits[0].hit, hits[0].size), (1, ctypes.sizeof(nl.RayHit)))
            # A host with a newer header: bigger elements, laid out at its stride, each size written back.
            stride = ctypes.sizeof(nl.RayHit) + 16
            wide = (ctypes.c_uint8 * (2 * stride))()
            ctypes.c_uint32.from_buffer(wide, 0).value = stride
            pair = (nl.Ray * 2)(ray, nl.Ray(nl.Vec3(0, 2, 0), nl.Vec3(0, 1, 0), 100))
            self.assertEqual(nl.lib.nl_world_cast_rays(world.pointer, pair, 2,
                                                       ctypes.cast(wide, ctypes.POINTER(nl.RayHit))), nl.STATUS_SUCCESS)
            first, second = nl.RayHit.from_buffer(wide, 0), nl.RayHit.from_buffer(wide, stride)
            self.assertEqual((first.size, first.hit, second.size, second.hit), (stride, 1, stride, 0))
            self.assertEqual(bytes(wide[ctypes.sizeof(nl.RayHit):stride]), bytes(16), "the host's extra bytes untouched")
        self.assertTrue(nl.failed(nl.lib.nl_world_create(None, None)))
        self.assertEqual(nl.lib.nl_world_get_worker_count(None), 0)
        self.assertTrue(nl.failed(nl.lib.nl_get_last_status()))

    def test_dungeon_obj(self):
        path = os.path.join(LEVELS, "dungeon.obj")
        with open(path) as f:
            expected = sum(len(line.split()) - 3 for line in f if line.split()[:1] == ["f"])
        with nl.World() as world:
            info = world.mesh_info(world.add_obj_file(path))
            self.assertEqual(info.triangle_count + info.degenerate_triangle_count, expected)


class NavmeshTest(NavLinkTestCase):
    def test_navmesh_from_the_level(self):
        with nl.World() as world:
            add_gap_level(world)
            recast = nl.default_recast_settings()
            self.assertAlmostEqual(recast.cell_size, 0.3, places=6)
            recast.cell_size = 0.2
            navmesh = world.build_navmesh(recast=recast, settings_json='{"edge_max_length": 6}')
            info = world.navmesh_info(navmesh)
            self.assertTrue(info.polygon_count >= 2 and info.boundary_edge_count >= 8)
            self.assertEqual(info.turned_over_mesh_count, 0, "the level's fronts are wound counter-clockwise")
            self.assertEqual(info.build_warnings, 0, "the level is in metres with y up")
            # Three islands: the platforms and the pit floor 20 m down, walkable but unreachable.
            self.assertTrue(-12 <= info.bounds_min[0] and info.bounds_max[0] <= 12 and info.bounds_max[1] < 0.5)
            self.assertTrue(-20.1 < info.bounds_min[1] < -19.5, info.bounds_min[1])
            self.assertEqual(len(world.navmesh_vertices(navmesh)), info.vertex_count)
            edges = world.boundary_edges(navmesh)
            self.assertEqual(len(edges), info.boundary_edge_count)
            self.assertTrue(all(abs(math.hypot(e.outward[0], e.outward[2]) - 1) < 1e-3 for e in edges))
            found = world.find_nearest(navmesh, [(-6, 3, 0), (0, 0, 0), (0, 0, 30)], (2, 4, 2))
            self.assertTrue(found[0].found == 1 and abs(found[0].point[0] + 6) < 1e-3 and found[0].point[1] < 0.5)
            self.assertTrue(found[1].found == 1 and abs(found[1].point[0]) >= 1.5)
            self.assertTrue(found[2].found == 0 and found[2].polygon == nl.NO_POLYGON)
            self.assertEqual(world.navmeshes(), [navmesh])
            # The settings struct reaches the builder: 3 corners per polygon turn the quads into triangles.
            triangles = nl.default_recast_settings()
            triangles.vertices_per_polygon = 3
            triangulated = world.build_navmesh(recast=triangles)
            count = world.navmesh_info(triangulated).polygon_count
            self.assertTrue(all(world.polygon(triangulated, i).vertex_count == 3 for i in range(count)))
            self.assertTrue(any(world.polygon(navmesh, i).vertex_count > 3 for i in range(info.polygon_count)))
            world.remove_navmesh(triangulated)
            self.assertFails(nl.STATUS_PARSE_ERROR, "settings", world.build_navmesh, settings_json="{oops")
            self.assertFails(nl.STATUS_NOT_FOUND, "nope", world.build_navmesh, builder="nope")
            world.remove_navmesh(navmesh)
            self.assertFalse(world.is_navmesh_valid(navmesh))
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_navmesh_get_info", world.navmesh_info, navmesh)
        with nl.World() as empty:
            self.assertFails(nl.STATUS_NOT_FOUND, "walkable", empty.build_navmesh)

    def test_navmesh_from_the_host(self):
        vertices = [0, 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0,
                    1, 0, 0, 1, 0, 1, 2, 0, 1, 1, 0, 0, 2, 0, 1, 2, 0, 0]
        indices = list(range(12))
        with nl.World() as world:
            navmesh = world.add_navmesh(vertices, indices, areas=[0, 0, 5, 5])
            info = world.navmesh_info(navmesh)
            self.assertEqual((info.vertex_count, info.welded_vertex_count, info.portal_count,
                              info.boundary_edge_count), (6, 6, 3, 6))
            polygon = world.polygon(navmesh, 2)
            linked = [n for n in polygon.neighbours[:polygon.vertex_count] if n != nl.NO_POLYGON]
            self.assertTrue(polygon.vertex_count == 3 and polygon.area == 5 and linked and
                            polygon.neighbours[15] == nl.NO_POLYGON)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "polygon", world.polygon, navmesh, 99)
            indices[2] = 40
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "indices", world.add_navmesh, vertices, indices)

    def test_tiles_out_and_in_again(self):
        """A 40 x 12 m floor built in tiles of 32 cells (9.6 m): the tiles listed are info's, in row order; one
        removed leaves a hole and is gone from the list, removed again it is not found; built again from the level
        in a box around its centre it is back (tile_size 64 refused, nothing changed); removed once more, a
        hand-made quad added as that tile fills the hole and joins its neighbours (a path crosses it)."""
        with nl.World() as world:
            add_box(world, TILED_FLOOR_LO, TILED_FLOOR_HI)
            recast = nl.default_recast_settings()
            self.assertEqual((recast.tile_size, recast.tile_border), (0, 0), "solo by default")
            recast.tile_size = 32
            navmesh = world.build_navmesh(recast=recast)
            info = world.navmesh_info(navmesh)
            tiles = world.tiles(navmesh)
            self.assertGreater(len(tiles), 1)
            self.assertEqual(len(tiles), info.tile_count)
            self.assertEqual(tiles, sorted(tiles, key=lambda t: (t[1], t[0])), "row order: z, then x")
            self.assertAlmostEqual(info.tile_width, 32 * recast.cell_size, places=4)
            width, origin = info.tile_width, tuple(info.tile_origin)
            # The tile under the floor's middle, and the quad of it the agent stands on (the floor eroded 0.6 m).
            middle = (20.0, 0.0, 3.0)
            tile = (int(math.floor((middle[0] - origin[0]) / width)), int(math.floor((middle[2] - origin[1]) / width)))
            self.assertIn(tile, tiles)
            self.assertIsNotNone(polygon_at(world, navmesh, middle))
            west, east = WEST_OF_TILED_FLOOR, EAST_OF_TILED_FLOOR
            self.assertEqual(world.find_path(nl.PathQuery(navmesh, west, east, walker())).outcome, nl.PATH_COMPLETE)

            world.remove_tile(navmesh, tile)
            after = world.tiles(navmesh)
            self.assertEqual(len(after), len(tiles) - 1)
            self.assertEqual(after, [t for t in tiles if t != tile])
            self.assertEqual(world.navmesh_info(navmesh).tile_count, len(after))
            self.assertIsNone(polygon_at(world, navmesh, middle), "a hole where the tile was")
            self.assertFails(nl.STATUS_NOT_FOUND, "no tile", world.remove_tile, navmesh, tile)
            self.assertFails(nl.STATUS_NOT_FOUND, "no tile", world.remove_tile, navmesh, nl.TileCoord(*tile))
            self.assertEqual(world.tiles(navmesh), after, "a refused removal changes nothing")

            # The tile built again from the level, with the same settings, in a small box around its centre.
            centre = (origin[0] + (tile[0] + 0.5) * width, 0.0, origin[1] + (tile[1] + 0.5) * width)
            box_min, box_max = (centre[0] - 0.5, -1.0, centre[2] - 0.5), (centre[0] + 0.5, 1.0, centre[2] + 0.5)
            world.build_tiles(navmesh, box_min, box_max, recast=recast)
            self.assertEqual(world.tiles(navmesh), tiles, "the built tile is back in its place")
            self.assertEqual(world.navmesh_info(navmesh).tile_count, len(tiles))
            self.assertIsNotNone(polygon_at(world, navmesh, middle), "the built tile fills the hole")
            self.assertEqual(world.find_path(nl.PathQuery(navmesh, west, east, walker())).outcome, nl.PATH_COMPLETE,
                             "the built tile joins its neighbours")
            # Settings making tiles of another width (64 cells) are refused, and change nothing.
            rebuilt = (world.navmesh_info(navmesh).polygon_count, world.navmesh_vertices(navmesh))
            wider = nl.default_recast_settings()
            wider.tile_size = 64
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "makes tiles of", world.build_tiles, navmesh, box_min, box_max,
                             recast=wider)
            self.assertEqual(world.tiles(navmesh), tiles, "a refused build changes no tile")
            self.assertEqual(world.navmesh_info(navmesh).tile_count, len(tiles))
            self.assertEqual((world.navmesh_info(navmesh).polygon_count, world.navmesh_vertices(navmesh)), rebuilt,
                             "a refused build changes no polygon")
            self.assertEqual(world.find_path(nl.PathQuery(navmesh, west, east, walker())).outcome, nl.PATH_COMPLETE)
            world.remove_tile(navmesh, tile)
            self.assertEqual(world.tiles(navmesh), after)

            # The host's tile: one quad over the tile's square within the eroded floor, on the navmesh's grid.
            x0, z0 = max(origin[0] + tile[0] * width, 0.6), max(origin[1] + tile[1] * width, 0.6)
            x1, z1 = min(origin[0] + (tile[0] + 1) * width, 39.4), min(origin[1] + (tile[1] + 1) * width, 11.4)
            quad = [x0, 0, z0, x0, 0, z1, x1, 0, z1, x1, 0, z0]
            place = nl.NavmeshTile(tile[0], tile[1], width, origin)
            world.add_tile(navmesh, place, quad, [0, 1, 2, 3], [4])
            self.assertEqual(world.tiles(navmesh), tiles)
            self.assertEqual(world.navmesh_info(navmesh).tile_count, len(tiles))
            self.assertIsNotNone(polygon_at(world, navmesh, middle), "the hand-made tile fills the hole")
            self.assertEqual(world.find_path(nl.PathQuery(navmesh, west, east, walker())).outcome, nl.PATH_COMPLETE,
                             "the tile joins its neighbours")
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "loaded already", world.add_tile, navmesh, place, quad,
                             [0, 1, 2, 3], [4])
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "another grid", world.add_tile, navmesh,
                             place._replace(x=99, width=width * 2), quad, [0, 1, 2, 3], [4])
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "not a tile", world.add_tile, navmesh, place._replace(width=0), quad,
                             [0, 1, 2, 3], [4])
            # A solo navmesh has no tiles and takes none.
            solo = world.add_navmesh(FLOOR, QUAD)
            self.assertEqual((world.tiles(solo), world.navmesh_info(solo).tile_count), ([], 0))
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "not tiled", world.remove_tile, solo, (0, 0))
            self.assertEqual(nl.AgentReason.TILE_UNLOADED, nl.AGENT_REASON_TILE_UNLOADED)

    def test_tiles_saved_and_loaded_as_tiles_files(self):
        """The gap level built in tiles of 32 cells (9.6 m), its links generated (the jumps start on one tile and
        land on another): every tile saved as a tile's file and described (a tile, its place, the world's content
        hash for it); the first tile's bytes loaded in a second world with the same level and the others added
        make the same tiles and links; one tile once through a file; a tile added twice refused."""
        with nl.World() as world, tempfile.TemporaryDirectory() as tmp:
            add_gap_level(world)
            recast = nl.default_recast_settings()
            recast.tile_size = 32
            navmesh = world.build_navmesh(recast=recast)
            world.generate_links(navmesh)
            info = world.navmesh_info(navmesh)
            tiles = world.tiles(navmesh)
            link_count = len(world.links(navmesh))
            self.assertGreater(len(tiles), 1)
            self.assertGreater(link_count, 0)

            files = [world.save_tile(navmesh, tile) for tile in tiles]
            tile_links = 0
            for tile, data in zip(tiles, files):
                self.assertIsInstance(data, bytes)
                described, _ = nl.describe_navmesh_file(data)
                self.assertEqual((described.is_tile, (described.tile.x, described.tile.z)), (1, tile))
                tile_hash = world.tile_hash(navmesh, tile)
                self.assertNotEqual(tile_hash, 0)
                self.assertEqual(described.content_hash, tile_hash, "tile %s" % (tile,))
                self.assertEqual(world.tile_hash(navmesh, nl.TileCoord(*tile)), tile_hash)
                self.assertEqual((described.tile_width, described.tile_origin_x, described.tile_origin_z),
                                 (info.tile_width, info.tile_origin[0], info.tile_origin[1]))
                self.assertEqual(described.file_size, len(data))
                tile_links += described.link_count
            self.assertEqual(tile_links, link_count, "each generated link in the file of the tile it starts on")
            whole, _ = nl.describe_navmesh_file(world.save_navmesh(navmesh))
            self.assertEqual((whole.is_tile, whole.content_hash), (0, 0), "a whole navmesh's file is no tile's")

            with nl.World() as other:
                add_gap_level(other)
                loaded = other.load_navmesh(files[0])
                self.assertEqual(other.tiles(loaded), [tiles[0]], "the first tile's file makes a navmesh of that tile")
                for data in files[1:]:
                    other.add_tile_bytes(loaded, data)
                self.assertEqual(other.tiles(loaded), tiles)
                self.assertEqual(len(other.links(loaded)), link_count)
                self.assertEqual(other.navmesh_info(loaded).polygon_count, info.polygon_count)

                # Once through a file: the tile with the most links, saved to a file, removed and added back from it.
                most = max(range(len(tiles)), key=lambda k: nl.describe_navmesh_file(files[k])[0].link_count)
                path = os.path.join(tmp, "tile.nlnav")
                world.save_tile_file(navmesh, tiles[most], path)
                with open(path, "rb") as f:
                    self.assertEqual(f.read(), files[most])
                other.remove_tile(loaded, tiles[most])
                self.assertEqual(len(other.tiles(loaded)), len(tiles) - 1)
                other.add_tile_file(loaded, path)
                self.assertEqual(other.tiles(loaded), tiles)
                self.assertEqual(len(other.links(loaded)), link_count, "its links back with it")

                self.assertFails(nl.STATUS_INVALID_ARGUMENT, "loaded already", other.add_tile_bytes, loaded, files[most])
                self.assertEqual((other.tiles(loaded), len(other.links(loaded))), (tiles, link_count), "nothing changed")


    def test_navmesh_on_a_moving_surface(self):
        """A navmesh that rides a movable mesh (its carrier): given in the mesh's space, answered in the world
        where the mesh is now; only rigid moves, and the mesh stays while the navmesh rides it."""
        with nl.World() as world:
            raft = add_box(world, RAFT_LO, RAFT_HI, flags=nl.MESH_MOVABLE)
            navmesh = world.add_navmesh(RAFT_QUAD, [0, 1, 2, 3], [4], carrier=raft)
            info = world.navmesh_info(navmesh)
            self.assertEqual((info.carrier, info.polygon_count), (raft, 1))
            on_raft, old_place = (10, 0.5, 3), (0, 0.5, 0)
            found = world.find_nearest(navmesh, [old_place, on_raft], (0.5, 2, 0.5))
            self.assertEqual([p.found for p in found], [1, 0], "before the move: at the origin")

            world.set_mesh_transform(raft, RAFT_MOVED)
            info = world.navmesh_info(navmesh)
            self.assertEqual(info.carrier, raft)
            self.assertTrue(info.bounds_min[0] <= 8.4 + 1e-3 and info.bounds_max[0] >= 11.6 - 1e-3 and
                            info.bounds_min[2] <= -3.6 + 1e-3 and info.bounds_max[2] >= 3.6 - 1e-3,
                            (list(info.bounds_min), list(info.bounds_max)))
            # (10, 3) is on the quad only if it was turned (its z half-width is 1.6 before).
            found = world.find_nearest(navmesh, [old_place, on_raft], (0.5, 2, 0.5))
            self.assertEqual(found[0].found, 0, "nothing left at the old place")
            self.assertEqual(found[1].found, 1)
            for got, want in zip(found[1].point, (10, 0, 3)):
                self.assertAlmostEqual(got, want, places=4)

            # Along the raft: the world's +z to -z is the mesh's -x to +x.
            path = world.find_path(nl.PathQuery(navmesh, (10, 0, 3), (10, 0, -3), walker()))
            self.assertEqual(path.outcome, nl.PATH_COMPLETE)
            self.assertAlmostEqual(path.info.length, 6, places=4)
            first, last = path.points[0], path.points[-1]
            for point, world_xyz, mesh_xyz in ((first, (10, 0, 3), (-3, 0, 0)), (last, (10, 0, -3), (3, 0, 0))):
                for got, want in zip(point.position, world_xyz):
                    self.assertAlmostEqual(got, want, places=4, msg="position (world)")
                for got, want in zip(point.carrier_position, mesh_xyz):
                    self.assertAlmostEqual(got, want, places=4, msg="carrier_position (the mesh's space)")

            # Only rigid moves for a mesh that carries a navmesh, and it cannot go while the navmesh rides it.
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "nl_mesh_set_transform", world.set_mesh_transform, raft,
                             RAFT_SCALED)
            self.assertEqual(list(world.mesh_info(raft).transform), RAFT_MOVED, "a refused move moves nothing")
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "nl_mesh_remove", world.remove_mesh, raft)

            # Recast on the raft alone, in its space, riding it; without a carrier a build sees static meshes only.
            built = world.build_navmesh(carrier=raft)
            self.assertEqual(world.navmesh_info(built).carrier, raft)
            self.assertEqual([p.found for p in world.find_nearest(built, [on_raft, old_place], (0.5, 2, 0.5))], [1, 0])
            self.assertFails(nl.STATUS_NOT_FOUND, "no triangles", world.build_navmesh)
            world.remove_navmesh(built)
            world.remove_navmesh(navmesh)
            world.remove_mesh(raft)

            # A navmesh on no carrier reports the null id, and its path points' carrier_position is position.
            ground = world.add_navmesh(FLOOR, QUAD)
            self.assertTrue(world.navmesh_info(ground).carrier.is_null)
            stroll = world.find_path(nl.PathQuery(ground, (-4, 0, -4), (4, 0, 4), walker()))
            self.assertTrue(all(list(q.carrier_position) == list(q.position) for q in stroll.points))

    def test_cross_link_onto_a_moving_surface(self):
        """A cross link (landing_navmesh) from a static ledge onto a navmesh riding a movable box: it holds while
        the box is where the link was placed, and its end moves with the box; one-way only."""
        with nl.World() as world:
            ledge = world.add_navmesh(LEDGE_QUAD, [0, 1, 2, 3], [4])
            deck_box = add_box(world, DECK_LO, DECK_HI, flags=nl.MESH_MOVABLE)
            deck = world.add_navmesh(DECK_QUAD, [0, 1, 2, 3], [4], carrier=deck_box)
            d = nl.default_link_def()
            self.assertTrue(d.landing_navmesh.is_null, "a link within one navmesh by default")
            self.assertAlmostEqual(d.tolerance, 0.25, places=6)
            d.start, d.end, d.landing_navmesh = CROSS_START, CROSS_END, deck  # in the world, the box beside the ledge
            cross = world.add_link(ledge, d)
            link = world.link(cross)
            self.assertEqual((link.navmesh, link.landing_navmesh, link.holds, link.bidirectional), (ledge, deck, 1, 0))
            self.assertAlmostEqual(link.tolerance, 0.25, places=6)
            self.assertNotEqual(link.end_polygon, nl.NO_POLYGON, "the end is on a polygon of the deck")
            self.assertNear(link.start, CROSS_START, "start")
            self.assertNear(link.end, CROSS_END, "end")

            world.set_mesh_transform(deck_box, DECK_AWAY)
            link = world.link(cross)
            self.assertEqual(link.holds, 0, "the box moved 2 m away: past the link's tolerance")
            self.assertNear(link.start, CROSS_START, "the start stays on the ledge")
            self.assertNear(link.end, CROSS_END_AWAY, "the end moved with the box")
            listed = world.links(ledge)
            self.assertEqual([(l.id, l.landing_navmesh, l.holds) for l in listed], [(cross, deck, 0)])
            self.assertNear(listed[0].end, CROSS_END_AWAY, "the listed end")

            world.set_mesh_transform(deck_box, DECK_HOME)
            link = world.link(cross)
            self.assertEqual(link.holds, 1, "the box is back")
            self.assertNear(link.end, CROSS_END, "the end is back")

            # A link within one navmesh: no landing navmesh, always holds, tolerance 0.
            within = nl.default_link_def()
            within.start, within.end = (-5, 0, 0), (-1, 0, 0)
            plain = world.link(world.add_link(ledge, within))
            self.assertTrue(plain.landing_navmesh.is_null and plain.holds == 1 and plain.tolerance == 0)

            # Cross links are one-way, lead to another live navmesh, and links files do not hold them.
            d.bidirectional = 1
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "bidirectional", world.add_link, ledge, d)
            d.bidirectional, d.landing_navmesh = 0, ledge
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "landing_navmesh", world.add_link, ledge, d)
            gone = world.add_navmesh(DECK_QUAD, [0, 1, 2, 3], [4])
            world.remove_navmesh(gone)
            d.landing_navmesh = gone
            self.assertFails(nl.STATUS_INVALID_HANDLE, "landing_navmesh", world.add_link, ledge, d)
            d.landing_navmesh, d.tolerance = deck, -1
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "tolerance", world.add_link, ledge, d)
            self.assertEqual(len(world.links(ledge)), 2, "nothing refused was added")
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "cross link", world.save_links_json, ledge)

    def test_cross_links_generated_for_where_a_platform_stands(self):
        """generate_cross_links: jumps both ways between a ledge and a platform 1 m off it, as generated cross
        links that hold while the platform stays there; 3 m off, none holds, none is found, and those made
        1 m off stay."""
        with nl.World() as world:
            add_box(world, LEDGE_BOX_LO, LEDGE_BOX_HI)
            platform = add_box(world, PLATFORM_LO, PLATFORM_HI, flags=nl.MESH_MOVABLE, transform=platform_at(9))
            agent = nl.default_agent_type()
            agent.radius = 0.3
            ledge = world.add_navmesh(LEDGE_TOP, [0, 1, 2, 3], [4], agent_type=agent)
            deck = world.add_navmesh(PLATFORM_TOP, [0, 1, 2, 3], [4], agent_type=agent, carrier=platform)
            settings = nl.default_link_settings()
            settings.max_jump_gap = 2.0

            def crossing(navmesh, landing):
                return [l for l in world.links(navmesh) if l.landing_navmesh == landing]

            stages = []
            report = world.generate_cross_links(ledge, deck, 0.25, settings,
                                                progress=lambda f, stage: stages.append((f, stage)) or True)
            onto, off = crossing(ledge, deck), crossing(deck, ledge)
            self.assertGreater(report.jump_links, 0)
            self.assertGreater(len(onto), 0, "links from the ledge onto the platform")
            self.assertGreater(len(off), 0, "links from the platform onto the ledge")
            self.assertEqual(report.jump_links + report.drop_links, len(onto) + len(off), "the report counts them")
            self.assertEqual(len(world.links(ledge)) + len(world.links(deck)), len(onto) + len(off),
                             "no links within either navmesh")
            self.assertTrue(stages and stages[-1][0] == 1.0, "progress reported: %s" % stages)
            for link in onto + off:
                self.assertEqual((link.generated, link.holds, link.bidirectional), (1, 1, 0))
                self.assertAlmostEqual(link.tolerance, 0.25, places=6)
                self.assertNotEqual(link.end_polygon, nl.NO_POLYGON)
            for link in onto:  # in the world: from the ledge's rim (x 5.7) to the platform's (x 7.3)
                self.assertTrue(5.5 < link.start[0] < 6 and 7 < link.end[0] < 7.5, "%s %s" % (list(link.start), list(link.end)))
            for link in off:
                self.assertTrue(7 < link.start[0] < 7.5 and 5.5 < link.end[0] < 6, "%s %s" % (list(link.start), list(link.end)))

            # 3 m off the ledge: nothing holds; beyond a 2 m jump nothing is found, and the links made 1 m off stay.
            world.set_mesh_transform(platform, platform_at(11))
            self.assertEqual([l.holds for l in crossing(ledge, deck) + crossing(deck, ledge)], [0] * (len(onto) + len(off)))
            report = world.generate_cross_links(ledge, deck, 0.25, settings)
            self.assertEqual((report.jump_links, report.drop_links), (0, 0))
            self.assertEqual([l.id for l in crossing(ledge, deck)], [l.id for l in onto], "kept for when it is back")
            self.assertEqual([l.id for l in crossing(deck, ledge)], [l.id for l in off])

            # Back 1 m off: they hold again, and generating there again replaces them (not doubled).
            world.set_mesh_transform(platform, platform_at(9))
            self.assertTrue(all(l.holds == 1 for l in crossing(ledge, deck) + crossing(deck, ledge)))
            world.generate_cross_links(ledge, deck, 0.25, settings)
            self.assertEqual((len(crossing(ledge, deck)), len(crossing(deck, ledge))), (len(onto), len(off)))

            # Refused: the same navmesh twice, a bad tolerance, another body, a stale navmesh; a cancel changes nothing.
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "nl_navmesh_generate_cross_links", world.generate_cross_links,
                             ledge, ledge, 0.25, settings)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "tolerance", world.generate_cross_links, ledge, deck, -1, settings)
            wide = world.add_navmesh(PLATFORM_TOP, [0, 1, 2, 3], [4])  # the default radius, 0.6
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "bodies", world.generate_cross_links, ledge, wide, 0.25, settings)
            world.remove_navmesh(wide)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "second", world.generate_cross_links, ledge, wide, 0.25, settings)
            before = [l.id for l in world.links(ledge)]
            self.assertFails(nl.STATUS_CANCELLED, "", world.generate_cross_links, ledge, deck, 0.25, settings,
                             progress=lambda f, stage: False)
            self.assertEqual([l.id for l in world.links(ledge)], before)


# A horizontal quad's triangles: counter-clockwise seen from above (its front faces up), and the same
# triangles wound the other way.
FRONT_UP, FRONT_DOWN = [0, 1, 2, 0, 2, 3], [0, 2, 1, 0, 3, 2]


def add_cell_row(world, row):
    """A navmesh of 1 m cells for radius 0: cell c of `row` ('.', or '#' for none) is x in [c, c + 1], z in
    [0, 1], y = 0; the cells become polygons in order."""
    columns = [c for c, cell in enumerate(row) if cell == "."]
    vertices = [v for c in columns for v in (c, 0, 0, c, 0, 1, c + 1, 0, 1, c + 1, 0, 0)]
    agent = nl.default_agent_type()
    agent.radius = 0
    return world.add_navmesh(vertices, list(range(4 * len(columns))), polygon_vertex_counts=[4] * len(columns),
                             agent_type=agent)


def cell_body(jump):
    agent = nl.default_agent_capabilities()
    agent.radius, agent.max_jump_distance = 0, jump
    return nl.QueryFilter(agent)


class QueryTest(NavLinkTestCase):
    """navlink.h's "Queries on a navmesh for one body" (tests/abi/queries_tests.c's cells): one row of 1 m cells,
    "..#..#..": polygons 0-1 (x in [0, 2]), 2-3 (x in [3, 5]) and 4-5 (x in [6, 8]), for radius 0; a one-way
    manual link from cell 1's centre to cell 3's (2 m: its gap). A jumper (3 m) takes it, a walker does not.
    And find_nearest's point beyond its box. The same checks as the C# and Rust tests."""
    START = (0.5, 0, 0.5)

    def setUp(self):
        self.world = nl.World()
        self.navmesh = add_cell_row(self.world, "..#..#..")
        link = nl.default_link_def()
        link.start, link.end = nl.Vec3(1.5, 0, 0.5), nl.Vec3(3.5, 0, 0.5)
        self.world.add_link(self.navmesh, link)
        self.walker, self.jumper = cell_body(0), cell_body(3)

    def tearDown(self):
        self.world.close()

    def test_defaults(self):
        raw = nl.lib.nl_default_query_filter()
        self.assertEqual((raw.size, raw.area_cost_count, bool(raw.area_costs)), (ctypes.sizeof(nl.QueryFilterDef), 0, False))
        default = nl.default_query_filter()
        self.assertEqual((default.capabilities.radius, list(default.area_costs)), (nl.default_agent_capabilities().radius, []))
        d = nl.lib.nl_default_random_points_def()
        self.assertEqual((d.size, d.radius, d.reachable_from, d.seed, bool(d.filter)),
                         (ctypes.sizeof(nl.RandomPointsDef), 0.0, nl.NO_POLYGON, 1, False))

    def test_reachability_one_way_across_a_link(self):
        w, navmesh, walker, jumper = self.world, self.navmesh, self.walker, self.jumper
        self.assertEqual(w.can_reach(navmesh, [0], [1], walker), [True], "a cell reaches its neighbour")
        self.assertEqual(w.can_reach(navmesh, [0], [1]), [False],
                         "the default walker (radius 0.6) does not fit through a 1 m portal")
        self.assertEqual(w.can_reach(navmesh, [1], [2], walker), [False], "a walker does not cross the gap")
        self.assertEqual(w.can_reach(navmesh, [0, 3, 5], [3, 0, 4], jumper), [True, False, True],
                         "the jumper takes the link; it does not lead back")
        self.assertEqual(w.can_reach(navmesh, array.array("I", [0]), array.array("I", [3]), filter=jumper), [True])
        self.assertEqual(w.reachable_polygons(navmesh, 1, jumper), [0, 1, 2, 3])
        self.assertEqual(w.reachable_polygons(navmesh, 1, walker), [0, 1])
        self.assertEqual(w.islands(navmesh, jumper), ([0, 0, 1, 1, 2, 2], 3))
        keep_out = nl.QueryFilter(jumper.capabilities, [nl.AREA_EXCLUDED])
        self.assertEqual(w.islands(navmesh, keep_out), ([nl.NO_ISLAND] * 6, 0), "keeping out of area 0 leaves no island")
        self.assertEqual(w.can_reach(navmesh, [0, 0], [1, 0], keep_out), [False, True],
                         "an excluded polygon is reached from nowhere else, but reaches itself")
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "to_polygons[0] is 6", w.can_reach, navmesh, [0], [6], jumper)
        with self.assertRaises(ValueError):
            w.can_reach(navmesh, [0, 1], [2])

    def test_raycast_stops_at_a_missing_cell_and_a_slide_follows_the_wall(self):
        w, navmesh = self.world, self.navmesh
        hit, crossed = w.raycast(navmesh, 0, self.START, (4.5, 0, 0.5))
        self.assertEqual(hit.hit, 1, "a raycast into a missing cell stops at its wall")
        self.assertAlmostEqual(hit.t, 0.375, delta=1e-4)
        self.assertNear(hit.point, (2, 0, 0.5), "at the wall")
        self.assertNear(hit.wall_normal, (-1, 0, 0), "facing back")
        self.assertEqual((hit.end_polygon, hit.polygon_count, crossed), (1, 2, [0, 1]))
        hit, crossed = w.raycast(navmesh, 0, self.START, (1.5, 0, 0.5), filter=nl.QueryFilter())
        self.assertEqual((hit.hit, hit.t, list(hit.wall_normal), hit.end_polygon, crossed), (0, 1.0, [0, 0, 0], 1, [0, 1]))
        self.assertNear(hit.point, (1.5, 0, 0.5), "arrives")
        # The single ray is a batch of one: the library names it rays[0].
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "rays[0].start is not over rays[0].start_polygon 2", w.raycast,
                         navmesh, 2, self.START, (1, 0, 1))

        moved, visited = w.move_along_surface(navmesh, 0, self.START, (2.5, 0, 0.5))
        self.assertEqual((moved.found, moved.polygon), (1, 1))
        self.assertNear(moved.point, (2, 0, 0.5), "a slide into a wall stops on it")
        self.assertAlmostEqual(moved.distance, 0.5, delta=1e-3)
        self.assertTrue(len(visited) >= 2 and visited[0] == 0 and visited[-1] == 1, visited)
        moved, _ = w.move_along_surface(navmesh, 0, self.START, (1.5, 0, 0.5), self.walker)
        self.assertEqual((moved.polygon, moved.distance), (1, 0.0))
        self.assertNear(moved.point, (1.5, 0, 0.5), "a clear slide arrives")

    def assertBatchAsSingleCalls(self, navmesh, rays, filter=None):
        """Each ray of a batch against the same ray alone, with and without polygons; the batch's walks."""
        walks = self.world.raycast_batch_with_polygons(navmesh, rays, filter)
        hits = self.world.raycast_batch(navmesh, rays, filter)
        self.assertEqual((len(walks), len(hits)), (len(rays), len(rays)), "one answer per ray")
        for i, ray in enumerate(rays):
            ray = ray if isinstance(ray, nl.NavmeshRay) else nl.NavmeshRay(*ray)
            hit, polygons = self.world.raycast(navmesh, ray.start_polygon, ray.start, ray.end, filter)
            self.assertEqual((bytes(walks[i][0]), walks[i][1]), (bytes(hit), polygons), "ray %d in a batch as alone" % i)
            self.assertEqual(bytes(hits[i]), bytes(hit), "ray %d without polygons" % i)
            self.assertEqual(hit.polygon_count, len(polygons), "ray %d: polygon_count counts the list" % i)
        return walks

    def test_a_batch_of_rays_answers_as_single_calls(self):
        w, navmesh = self.world, self.navmesh
        rays = [nl.NavmeshRay(self.START, 0, (4.5, 0, 0.5)),      # into the missing cell
                (self.START, 0, (1.5, 0, 0.5)),                    # arrives (a tuple in the struct's order)
                nl.NavmeshRay((3.5, 0, 0.5), 2, (0.5, 0, 0.5)),    # west into the gap
                nl.NavmeshRay((6.5, 0, 0.25), 4, (7.5, 0, 0.75)),  # across the last island
                nl.NavmeshRay((1.5, 0, 0.5), 1, (1.5, 0, 3))]      # out through the side
        walks = self.assertBatchAsSingleCalls(navmesh, rays, self.jumper)
        self.assertEqual((walks[0][0].hit, walks[0][1], walks[1][0].hit), (1, [0, 1], 0))
        self.assertNear(walks[0][0].point, (2, 0, 0.5), "at the wall")
        self.assertEqual((walks[2][0].hit, walks[2][1]), (1, [2]))
        self.assertNear(walks[2][0].point, (3, 0, 0.5), "at the gap's east wall")
        self.assertNear(walks[2][0].wall_normal, (1, 0, 0), "facing back east")
        self.assertEqual((walks[3][0].hit, walks[3][0].end_polygon, walks[3][1]), (0, 5, [4, 5]))
        self.assertEqual(walks[4][0].hit, 1)
        self.assertNear(walks[4][0].point, (1.5, 0, 1), "at the side")
        self.assertNear(walks[4][0].wall_normal, (0, 0, -1), "facing back in")
        self.assertEqual((w.raycast_batch(navmesh, []), w.raycast_batch_with_polygons(navmesh, [])), ([], []))

        refused = [nl.NavmeshRay.from_buffer_copy(r if isinstance(r, nl.NavmeshRay) else nl.NavmeshRay(*r)) for r in rays]
        refused[3].start_polygon = 2
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "rays[3].start is not over rays[3].start_polygon 2",
                         w.raycast_batch, navmesh, refused)
        # Raw: a refused batch writes nothing; a batch's polygons go to i * polygons_per_ray.
        raw_rays = (nl.NavmeshRay * 5)(*refused)
        hits = (nl.NavmeshRaycastHit * 5)(*[nl.NavmeshRaycastHit() for _ in range(5)])
        polygons = (ctypes.c_uint32 * 20)(*[7] * 20)
        status = nl.lib.nl_navmesh_raycast(w.pointer, navmesh, None, raw_rays, 5, hits, polygons, 4)
        self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT)
        self.assertEqual([bytes(h) for h in hits], [bytes(nl.NavmeshRaycastHit())] * 5, "no hit written")
        self.assertEqual(list(polygons), [7] * 20, "no polygon written")
        raw_rays[3].start_polygon = 4
        self.assertEqual(nl.lib.nl_navmesh_raycast(w.pointer, navmesh, None, raw_rays, 5, hits, polygons, 4),
                         nl.STATUS_SUCCESS)
        self.assertEqual((hits[3].polygon_count, list(polygons[12:14])), (2, [4, 5]), "ray 3's polygons at 3 * 4")

    def test_random_points_are_on_the_navmesh_and_repeat_with_their_seed(self):
        w, navmesh = self.world, self.navmesh
        points = w.random_points(navmesh, 50, seed=7)
        cell_x = [0, 1, 3, 4, 6, 7]
        self.assertEqual(len(points), 50)
        for p in points:
            self.assertTrue(p.found == 1 and p.distance == 0 and p.point[1] == 0 and p.polygon < 6)
            self.assertTrue(cell_x[p.polygon] <= p.point[0] <= cell_x[p.polygon] + 1 and 0 <= p.point[2] <= 1,
                            "on its polygon: %s %d" % (list(p.point), p.polygon))
        again = w.random_points(navmesh, 50, seed=7)
        self.assertEqual([bytes(p) for p in again], [bytes(p) for p in points], "the same seed gives the same points")
        self.assertNotEqual([bytes(p) for p in w.random_points(navmesh, 50, seed=8)], [bytes(p) for p in points])
        points = w.random_points(navmesh, 50, filter=self.jumper, reachable_from=4, seed=7)
        self.assertTrue(len(points) == 50 and all(p.polygon in (4, 5) for p in points), "the last island only")
        points = w.random_points(navmesh, 50, centre=self.START, radius=0.5)
        self.assertTrue(len(points) == 50 and all(horizontal(p.point, self.START) <= 0.5 + 1e-4 for p in points))
        keep_out = nl.QueryFilter(area_costs=array.array("f", [nl.AREA_EXCLUDED]))
        self.assertEqual(w.random_points(navmesh, 10, filter=keep_out), [], "none outside the excluded area")

    def test_find_nearest_reports_the_point_beyond_its_box(self):
        missed, hit = self.world.find_nearest(self.navmesh, [(12, 0, 0.5), self.START], (1, 1, 1))
        self.assertEqual((missed.found, missed.beyond_box, missed.polygon), (0, 1, nl.NO_POLYGON))
        self.assertNear(missed.point, (8, 0, 0.5), "the navmesh's nearest point beyond the box")
        self.assertAlmostEqual(missed.distance, 4, delta=1e-3)
        self.assertEqual((hit.found, hit.beyond_box, hit.polygon), (1, 0, 0))

    def test_walks_longer_than_the_first_buffer(self):
        """40 cells in a row: a walk from the first to the last crosses 40 polygons, more than the binding's
        first buffer holds, so it asks again."""
        row = add_cell_row(self.world, "." * 40)
        hit, crossed = self.world.raycast(row, 0, self.START, (39.5, 0, 0.5))
        self.assertEqual((hit.hit, hit.polygon_count, crossed), (0, 40, list(range(40))))
        moved, visited = self.world.move_along_surface(row, 0, self.START, (39.5, 0, 0.5))
        self.assertEqual((moved.polygon, visited), (39, list(range(40))))
        self.assertNear(moved.point, (39.5, 0, 0.5), "arrives")

        # A batch of long and short walks: those that crossed more than 32 are walked again, together.
        rays = [nl.NavmeshRay(self.START, 0, (39.5, 0, 0.5)), nl.NavmeshRay(self.START, 0, (1.5, 0, 0.5)),
                nl.NavmeshRay((39.5, 0, 0.5), 39, (2.5, 0, 0.5)), nl.NavmeshRay((10.5, 0, 0.5), 10, (45, 0, 0.5)),
                nl.NavmeshRay((20.5, 0, 0.5), 20, (20.5, 0, 0.5))]
        walks = self.assertBatchAsSingleCalls(row, rays)
        self.assertEqual([hit.polygon_count for hit, _ in walks], [40, 2, 38, 30, 1])
        self.assertEqual((walks[0][1], walks[2][1], walks[4][1]), (list(range(40)), list(range(39, 1, -1)), [20]),
                         "all, backwards, and a ray of no length")
        self.assertEqual((walks[3][0].hit, walks[4][0].t), (1, 1.0))
        self.assertNear(walks[3][0].point, (40, 0, 0.5), "out of the row's end")


def add_quad(world, x0, z0, x1, z1, y, winding, flags=0, area=0):
    """A horizontal quad, x in [x0, x1], z in [z0, z1] at height y."""
    return world.add_mesh([x0, y, z0, x0, y, z1, x1, y, z1, x1, y, z0], winding, flags=flags, area=area)


def polygon_at(world, navmesh, point):
    """The navmesh polygon within (0.4, 0.3, 0.4) of the point, or None."""
    hit = world.find_nearest(navmesh, [point], (0.4, 0.3, 0.4))[0]
    return world.polygon(navmesh, hit.polygon) if hit.found else None


class MeshInputTest(NavLinkTestCase):
    """What a navmesh build takes from the level (tests/abi/navmesh_build_tests.c's winding, mesh_roles,
    mesh_areas and build_progress, with their geometry), a mesh's units, and a build's progress and cancel."""

    def test_a_clockwise_floor_builds_only_with_the_clockwise_flag(self):
        with nl.World() as world:
            # Wound clockwise (fronts down): nothing to walk on, and the message names the flag to set.
            floor = add_quad(world, -10, -10, 10, 10, 0, FRONT_DOWN)
            self.assertFails(nl.STATUS_NOT_FOUND, "NL_MESH_CLOCKWISE", world.build_navmesh)
            world.remove_mesh(floor)
            floor = add_quad(world, -10, -10, 10, 10, 0, FRONT_DOWN, flags=nl.MESH_CLOCKWISE)
            self.assertEqual(world.mesh_info(floor).flags, nl.MESH_CLOCKWISE)
            self.assertIsNotNone(polygon_at(world, world.build_navmesh(), (0, 0, 0)),
                                 "the same floor flagged clockwise is walked on")

    def test_an_obstacle_crate_is_not_walked_on_and_a_left_out_slab_is_not_built(self):
        with nl.World() as world:
            add_quad(world, -10, -10, 10, 10, 0, FRONT_UP)
            # A 4 x 4 x 1 m crate, x and z in [3, 7]: its top is walkable as any floor, unless it is an obstacle.
            crate = add_box(world, (3, 0, 3), (7, 1, 7))
            self.assertIsNotNone(polygon_at(world, world.build_navmesh(), (5, 1, 5)), "an ordinary crate's top")
            world.remove_mesh(crate)
            crate = add_box(world, (3, 0, 3), (7, 1, 7), flags=nl.MESH_OBSTACLE)
            self.assertEqual(world.mesh_info(crate).flags, nl.MESH_OBSTACLE)
            navmesh = world.build_navmesh()
            self.assertIsNone(polygon_at(world, navmesh, (5, 1, 5)), "an obstacle crate's top is not walked on")
            self.assertIsNone(polygon_at(world, navmesh, (5, 0, 5)), "the floor under the obstacle is blocked")
            self.assertIsNotNone(polygon_at(world, navmesh, (-5, 0, 5)), "the floor beside it is walkable")

            # A slab 1 m over the floor leaves no headroom; left out of builds it leaves the floor, and rays meet it.
            slab = add_quad(world, -8, -8, -2, -2, 1, FRONT_DOWN)
            self.assertIsNone(polygon_at(world, world.build_navmesh(), (-5, 0, -5)), "no headroom under the slab")
            world.remove_mesh(slab)
            slab = add_quad(world, -8, -8, -2, -2, 1, FRONT_DOWN, flags=nl.MESH_NOT_IN_NAVMESH)
            self.assertIsNotNone(polygon_at(world, world.build_navmesh(), (-5, 0, -5)), "a left-out slab leaves the floor")
            hit = world.cast_rays([nl.Ray(nl.Vec3(-5, 5, -5), nl.Vec3(0, -1, 0), 10)])[0]
            self.assertTrue(hit.hit == 1 and hit.mesh == slab and abs(hit.point[1] - 1) < 1e-4, "a ray meets the slab")
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "", add_quad, world, 0, 0, 1, 1, 0, FRONT_UP,
                             flags=nl.MESH_OBSTACLE | nl.MESH_NOT_IN_NAVMESH)

    def test_a_mesh_area_is_carried_into_the_built_polygons(self):
        with nl.World() as world:
            add_quad(world, -10, -10, 0, 10, 0, FRONT_UP)
            east = add_quad(world, 0, -10, 10, 10, 0, FRONT_UP, area=5)
            self.assertEqual(world.mesh_info(east).area, 5)
            navmesh = world.build_navmesh()
            east_polygon, west_polygon = polygon_at(world, navmesh, (5, 0, 0)), polygon_at(world, navmesh, (-5, 0, 0))
            self.assertTrue(east_polygon is not None and east_polygon.area == 5, "the polygon over the east mesh")
            self.assertTrue(west_polygon is not None and west_polygon.area == 0, "the polygon over the west mesh")
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "area", add_quad, world, 0, 0, 1, 1, 0, FRONT_UP,
                             area=nl.MESH_MAX_AREA + 1)

    def test_a_level_in_centimetres_is_registered_in_metres(self):
        # The 10 x 10 m box, 1 m thick, as an exporter in centimetres writes it.
        box = box_vertices((-500, -100, -500), (500, 0, 500))
        logged = []
        with nl.World(log=lambda level, status, message: logged.append((level, message))) as world:
            mesh = world.add_mesh(box, BOX_INDICES, metres_per_unit=0.01, up_axis=nl.UP_AXIS_Y)
            info = world.mesh_info(mesh)
            self.assertEqual((info.metres_per_unit, info.up_axis), (ctypes.c_float(0.01).value, nl.UP_AXIS_Y))
            self.assertNear(info.bounds_min, (-5, -1, -5), "the bounds in metres")
            self.assertNear(info.bounds_max, (5, 0, 5), "the bounds in metres")
            self.assertEqual(world.navmesh_info(world.build_navmesh()).build_warnings, 0)
            world.remove_mesh(mesh)
            # Not said, its walls are 100 m tall for a body of 2 m. Coarse cells: read as metres it is 1 km wide.
            world.add_mesh(box, BOX_INDICES)
            navmesh = world.build_navmesh(settings_json='{"cell_size": 2.0, "cell_height": 0.5}')
            self.assertEqual(world.navmesh_info(navmesh).build_warnings, nl.BUILD_WARNING_UNITS)
            self.assertIn("metres_per_unit", " ".join(m for level, m in logged if level == nl.LOG_WARNING))

    def test_a_build_reports_progress_and_can_be_cancelled(self):
        with nl.World() as world:
            add_box(world, (-10, 0, -10), (10, 1, 10))
            calls = []
            world.build_navmesh(progress=lambda f, stage: calls.append((f, stage, threading.get_ident())) or True)
            fractions = [f for f, _, _ in calls]
            self.assertGreaterEqual(len(fractions), 2)
            self.assertTrue(all(b >= a for a, b in zip(fractions, fractions[1:])), "never goes back: %s" % fractions)
            self.assertEqual((fractions[0], fractions[-1]), (0.0, 1.0))
            self.assertIn("rasterising the level", {stage for _, stage, _ in calls})
            self.assertEqual({thread for _, _, thread in calls}, {threading.get_ident()}, "on the calling thread")

            # Cancelled while rasterising: STATUS_CANCELLED, no navmesh added, nothing reported after the cancel.
            stages = []

            def cancel_while_rasterising(fraction, stage):
                stages.append(stage)
                return stage != "rasterising the level"
            self.assertFails(nl.STATUS_CANCELLED, "cancelled", world.build_navmesh, progress=cancel_while_rasterising)
            self.assertEqual(stages[-1], "rasterising the level", "the build stopped at its cancel: %s" % stages)
            self.assertEqual(len(world.navmeshes()), 1, "a cancelled build adds no navmesh")

            def boom(fraction, stage):
                raise KeyError("progress raises")
            self.assertRaises(KeyError, world.build_navmesh, progress=boom)
            self.assertEqual(len(world.navmeshes()), 1, "a build whose progress raised adds nothing")


class LinkTest(NavLinkTestCase):
    def test_generated_jump_links(self):
        with nl.World() as world:
            add_gap_level(world)
            navmesh = world.build_navmesh()
            caller, seen = threading.get_ident(), []
            report = world.generate_links(navmesh, progress=lambda f, stage: seen.append((f, threading.get_ident())) or True)
            links = world.links(navmesh)
            self.assertTrue(report.jump_links >= 5 and report.drop_links == 0 and len(links) == report.jump_links)
            for link in links:
                self.assertTrue(link.kind == nl.LINK_JUMP and link.generated == 1 and link.bidirectional == 1)
                self.assertAlmostEqual(link.requirements.gap, 2.0, delta=0.05)  # rim to rim
                self.assertTrue(3.1 <= link.requirements.length <= 3.9)
                self.assertAlmostEqual(link.requirements.length, horizontal(link.start, link.end), places=3)
                self.assertTrue(min(link.start[0], link.end[0]) < -1 and max(link.start[0], link.end[0]) > 1)
                self.assertGreater(link.apex[1], max(link.start[1], link.end[1]))
            self.assertTrue(len(seen) >= 2 and seen[-1][0] == 1.0 and all(t == caller for _, t in seen))

            short = nl.link_settings_from_json('{"max_jump_gap": 1.8}')
            self.assertAlmostEqual(short.max_jump_gap, 1.8, places=6)
            none = world.generate_links(navmesh, short)
            self.assertTrue(none.jump_links == 0 and none.rejected_distance > 0 and not world.links(navmesh))
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "max_link_dist", nl.link_settings_from_json, '{"max_link_dist": 3}')

            world.generate_links(navmesh)
            before = [bytes(link) for link in world.links(navmesh)]
            self.assertFails(nl.STATUS_CANCELLED, "", world.generate_links, navmesh, progress=lambda f, s: False)
            self.assertEqual([bytes(link) for link in world.links(navmesh)], before)

            def boom(fraction, stage):
                raise KeyError("progress raises")
            self.assertRaises(KeyError, world.generate_links, navmesh, progress=boom)
            self.assertEqual([bytes(link) for link in world.links(navmesh)], before, "the generation was cancelled")

            add_box(world, (-0.1, -20, -6), (0.1, 6, 6))
            walled = world.update_links_in_box(navmesh, (-0.2, -21, -7), (0.2, 7, 7))
            self.assertTrue(walled.jump_links == 0 and not world.links(navmesh))
            self.assertEqual(world.remove_generated_links(navmesh), 0)

    def test_manual_links_and_json(self):
        with nl.World() as world:
            add_gap_level(world)
            navmesh = world.build_navmesh()
            world.generate_links(navmesh)
            generated = len(world.links(navmesh))
            d = nl.default_link_def()
            self.assertTrue(d.kind == nl.LINK_MANUAL and d.enabled == 1 and d.cost_modifier == 1 and
                            d.requirements_as_given == 0)
            d.start, d.end, d.user_data = nl.Vec3(-5, 0, 4), nl.Vec3(5, 0, 4), 7
            d.requirements.gap = 99  # measured from the ends instead
            manual = world.add_link(navmesh, d)
            got = world.link(manual)
            self.assertTrue(got.kind == nl.LINK_MANUAL and got.generated == 0 and got.user_data == 7)
            self.assertTrue(got.id == manual and got.navmesh == navmesh)
            self.assertAlmostEqual(got.requirements.gap, 10, places=4)

            # Requirements taken as given: a link across the gap that asks only for an ability.
            ability = nl.default_link_def()
            ability.start, ability.end = nl.Vec3(-5, 0, -4), nl.Vec3(5, 0, -4)
            ability.requirements_as_given, ability.requirements.abilities = 1, 4
            ability_link = world.add_link(navmesh, ability)
            r = world.link(ability_link).requirements
            self.assertEqual((r.gap, r.rise, r.drop, r.abilities), (0, 0, 0, 4))
            self.assertAlmostEqual(r.length, 10, places=4, msg="a length of 0 is measured")
            able = walker()
            able.abilities = 4
            across = world.find_path(nl.PathQuery(navmesh, WEST, EAST, able))
            self.assertEqual(across.outcome, nl.PATH_COMPLETE)
            self.assertIn(ability_link, [p.link for p in across.points])
            self.assertEqual(world.find_path(nl.PathQuery(navmesh, WEST, EAST, walker())).outcome, nl.PATH_PARTIAL)
            world.remove_link(ability_link)
            d.enabled = 0
            world.update_link(manual, d)
            self.assertEqual(world.link(manual).enabled, 0)
            self.assertEqual(world.remove_generated_links(navmesh), generated)
            self.assertEqual(len(world.links(navmesh)), 1)
            world.generate_links(navmesh)
            json = world.save_links_json(navmesh)
            self.assertIn("navlink-links", json)
            self.assertEqual(world.load_links_json(navmesh, json), generated + 1)
            self.assertFalse(world.is_link_valid(manual))
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_link_remove", world.remove_link, manual)
            self.assertFails(nl.STATUS_PARSE_ERROR, "nl_navmesh_load_links_json", world.load_links_json, navmesh, "[1,")
            d.end = nl.Vec3(0, 0, 0)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "def->end", world.add_link, navmesh, d)

    def test_links_json_for_another_body(self):
        """Links saved from a navmesh for radius 0.6 are refused by one for radius 0.3 (both bodies named,
        nothing changed) unless any_body, which loads them with a warning; a navmesh for the same body loads
        them."""
        logged = []
        with nl.World(log=lambda level, status, message: logged.append(message)) as world:
            add_gap_level(world)
            wide = world.build_navmesh()  # radius 0.6
            world.generate_links(wide)
            d = nl.default_link_def()
            d.start, d.end = nl.Vec3(-5, 0, 4), nl.Vec3(5, 0, 4)
            world.add_link(wide, d)
            count = len(world.links(wide))
            saved = world.save_links_json(wide)
            self.assertIn('"made_for"', saved)
            self.assertIn("made_for", json.loads(saved))

            slim = nl.default_agent_type()
            slim.radius = 0.3
            narrow = world.build_navmesh(slim)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "radius 0.6", world.load_links_json, narrow, saved)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "radius 0.3", world.load_links_json, narrow, saved,
                             any_body=False)
            self.assertEqual(len(world.links(narrow)), 0, "a refused load changes nothing")
            del logged[:]
            self.assertEqual(world.load_links_json(narrow, saved, any_body=True), count)
            self.assertEqual(len(world.links(narrow)), count)
            self.assertTrue(any("radius 0.6" in m and "radius 0.3" in m for m in logged),
                            "any_body warns to the log, naming both bodies: %r" % logged)

            same = world.build_navmesh()
            self.assertEqual(world.load_links_json(same, saved), count)
            self.assertEqual(world.load_links_json(wide, saved), count)


class NavmeshFileTest(NavLinkTestCase):
    def test_baked_navmesh_file(self):
        """Saved to bytes and to a file, described, loaded into a new world: the same polygons, links and
        paths; truncated and foreign bytes refused with nothing added."""
        with nl.World() as world, tempfile.TemporaryDirectory() as tmp:
            navmesh = gap_level_with_links(world)
            d = nl.default_link_def()
            d.start, d.end = nl.Vec3(-5, 0, 4), nl.Vec3(5, 0, 4)
            world.add_link(navmesh, d)
            link_count = len(world.links(navmesh))
            polygons = world.navmesh_info(navmesh).polygon_count
            original = world.find_path(nl.PathQuery(navmesh, WEST, EAST, jumper()))
            self.assertEqual(original.outcome, nl.PATH_COMPLETE)
            data = world.save_navmesh(navmesh)
            self.assertIsInstance(data, bytes)

            info, made_for = nl.describe_navmesh_file(data)
            self.assertEqual((info.size, info.file_size), (ctypes.sizeof(nl.NavmeshFileInfo), len(data)))
            self.assertGreaterEqual(info.version, 1)
            self.assertEqual(info.polygon_count, polygons)
            self.assertEqual((info.link_count, info.generated_link_count), (link_count, link_count - 1))
            self.assertAlmostEqual(info.agent_type.radius, 0.6, places=6)
            self.assertEqual(info.quantum, 1 / 1024)
            self.assertEqual(info.rides_carrier, 0)
            made_for = json.loads(made_for)
            self.assertIn("builder", made_for)
            self.assertEqual(made_for["builder"], "recast")
            self.assertEqual(made_for["level_hash"], "%016x" % info.level_hash)

            def assert_same(w, loaded):
                self.assertEqual(w.navmesh_info(loaded).polygon_count, polygons)
                self.assertEqual(len(w.links(loaded)), link_count)
                path = w.find_path(nl.PathQuery(loaded, WEST, EAST, jumper()))
                self.assertEqual(path.outcome, nl.PATH_COMPLETE)
                self.assertAlmostEqual(path.info.length, original.info.length, delta=1e-4)

            with nl.World() as fresh:
                loaded = fresh.load_navmesh(data)
                assert_same(fresh, loaded)
                self.assertEqual(fresh.save_navmesh(loaded), data, "what it was made for travels with it")

            path = os.path.join(tmp, "gap.nlnav")
            world.save_navmesh_file(navmesh, path)
            with open(path, "rb") as f:
                self.assertEqual(f.read(), data)
            with nl.World() as fresh:
                assert_same(fresh, fresh.load_navmesh_file(path))

            # The level it was baked from: same_level refuses a world without it, takes one with it.
            with nl.World() as other:
                self.assertFails(nl.STATUS_INVALID_ARGUMENT, "baked from", other.load_navmesh, data, same_level=True)
                self.assertEqual(other.navmeshes(), [])
                add_gap_level(other)
                assert_same(other, other.load_navmesh(data, same_level=True))

                count = len(other.navmeshes())
                self.assertFails(nl.STATUS_PARSE_ERROR, "nl_navmesh_load", other.load_navmesh, data[:len(data) // 2])
                self.assertFails(nl.STATUS_VERSION_MISMATCH, "nl_navmesh_load", other.load_navmesh, b"hello")
                self.assertFails(nl.STATUS_PARSE_ERROR, "nl_navmesh_file_describe", nl.describe_navmesh_file,
                                 data[:len(data) // 2])
                self.assertFails(nl.STATUS_VERSION_MISMATCH, "nl_navmesh_file_describe", nl.describe_navmesh_file, b"hello")
                self.assertFails(nl.STATUS_NOT_FOUND, "nl_navmesh_load_file", other.load_navmesh_file,
                                 os.path.join(tmp, "missing.nlnav"))
                self.assertEqual(len(other.navmeshes()), count, "nothing added on failure")


class PathTest(NavLinkTestCase):
    def test_walker_and_jumper_planned_now(self):
        with nl.World() as world:
            navmesh = gap_level_with_links(world)
            self.assertJumperAcross(world, world.find_path(nl.PathQuery(navmesh, WEST, EAST, jumper())))
            self.assertWalkerStopsAtGap(world.find_path(nl.PathQuery(navmesh, WEST, EAST, walker())))
            no_partial = nl.PathQuery(navmesh, WEST, EAST, walker())
            no_partial.accept_partial = False
            none = world.find_path(no_partial)
            self.assertTrue(none.outcome == nl.PATH_NO_PATH and not none.points)
            too_short = world.find_path(nl.PathQuery(navmesh, WEST, EAST, jumper(distance=1.8)))
            self.assertTrue(too_short.outcome == nl.PATH_PARTIAL and too_short.info.links_used == 0)
            stroll = world.find_path(nl.PathQuery(navmesh, (-9, 0, -3), (-3, 0, 3), walker()))
            self.assertTrue(stroll.outcome == nl.PATH_COMPLETE and stroll.info.links_used == 0)
            self.assertTrue(all(q.segment == nl.SEGMENT_WALK for q in stroll.points))
            self.assertTrue(8.48 <= stroll.info.length < 8.6, stroll.info.length)
            off = world.find_path(nl.PathQuery(navmesh, (0, -10, 30), EAST, jumper()))
            self.assertEqual(off.outcome, nl.PATH_START_OFF_NAVMESH)
            off = world.find_path(nl.PathQuery(navmesh, WEST, (0, -10, 30), jumper()))
            self.assertEqual(off.outcome, nl.PATH_GOAL_OFF_NAVMESH)

    def test_why_a_path_falls_short(self):
        with nl.World() as world:
            # A platform 4.2 m above a floor, no stairs, no links: its top is an island of the navmesh.
            add_box(world, (-10, -1, -10), (20, 0, 10))
            add_box(world, (0, 0, -3), (6, 4.2, 3))
            navmesh = world.build_navmesh()
            down = nl.PathQuery(navmesh, (3, 4.2, 0), (15, 0, 0), walker())
            down.accept_partial = True
            stuck = world.explain_path(down)
            self.assertIs(stuck.reason, nl.PathShortfallReason.NO_LINKS, stuck)
            self.assertEqual(stuck.reason, nl.PATH_SHORTFALL_NO_LINKS)
            self.assertTrue(stuck.limit == nl.LINK_LIMIT_NONE and stuck.link.is_null, stuck)
            self.assertIsInstance(stuck.text, str)
            self.assertIn("the navmesh has no links", stuck.text)
            stroll = world.explain_path(nl.PathQuery(navmesh, (15, 0, 0), (18, 0, 0), walker()))
            self.assertEqual((stroll.reason, stroll.text), (nl.PATH_SHORTFALL_NONE, ""))
            d = nl.lib.nl_default_path_request_def()
            d.navmesh = navmesh
            status = nl.lib.nl_path_explain(world.pointer, ctypes.byref(d), None)
            self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT, hex(status))
            self.assertIn("out_shortfall", nl.last_error_message())

    def test_queued_with_path_workers_and_callbacks(self):
        with nl.World() as world:
            navmesh = gap_level_with_links(world)
            calls, done = [], threading.Semaphore(0)

            def finished(name):
                return lambda ticket, outcome: (calls.append((name, ticket, outcome)), done.release())
            walker_ticket = world.request_path(nl.PathQuery(navmesh, WEST, EAST, walker()), finished("walker"))
            jumper_ticket = world.request_path(nl.PathQuery(navmesh, WEST, EAST, jumper()), finished("jumper"))
            self.assertNotEqual(walker_ticket, jumper_ticket)
            self.assertTrue(done.acquire(timeout=20) and done.acquire(timeout=20), "both callbacks ran")
            self.assertEqual(sorted(calls, key=lambda c: c[0]), [("jumper", jumper_ticket, nl.PATH_COMPLETE),
                                                                  ("walker", walker_ticket, nl.PATH_PARTIAL)])
            self.assertEqual(world.poll_path(walker_ticket), nl.PATH_PARTIAL)
            self.assertWalkerStopsAtGap(world.path_result(walker_ticket))
            jumped = world.path_result(jumper_ticket)
            self.assertJumperAcross(world, jumped)
            direct = world.find_path(nl.PathQuery(navmesh, WEST, EAST, jumper()))
            self.assertEqual([bytes(p) for p in direct.points], [bytes(p) for p in jumped.points])
            world.release_path(walker_ticket)
            world.release_path(jumper_ticket)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_poll", world.poll_path, walker_ticket)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_release", world.release_path, jumper_ticket)
            self.assertEqual(len(calls), 2, "each callback ran once")
            self.assertEqual(world.path_queue_stats().unreleased, 0)

    def test_queued_and_run_by_the_host(self):
        world = nl.World(path_worker_count=0)
        navmesh = gap_level_with_links(world)
        jumper_ticket = world.request_path(nl.PathQuery(navmesh, WEST, EAST, jumper()))
        seen = []
        doomed = world.request_path(nl.PathQuery(navmesh, WEST, EAST, walker()),
                                    lambda t, o: seen.append((o, threading.get_ident())))
        stats = world.path_queue_stats()
        self.assertEqual((stats.workers, stats.queued, stats.submitted), (0, 2, 2))
        self.assertEqual(world.poll_path(jumper_ticket), nl.PATH_PENDING)
        self.assertIsNone(world.path_result(jumper_ticket), "no result while pending")
        world.cancel_path(doomed)
        self.assertEqual(seen, [(nl.PATH_CANCELLED, threading.get_ident())], "cancelled at once, on this thread")
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "nl_path_process", world.process_paths, 0, float("nan"))
        self.assertEqual(world.process_paths(), 1)
        self.assertJumperAcross(world, world.path_result(jumper_ticket))
        stats = world.path_queue_stats()
        self.assertEqual((stats.finished, stats.unreleased, stats.queued), (2, 2, 0))
        last = []
        pending = world.request_path(nl.PathQuery(navmesh, WEST, EAST, jumper()), lambda t, o: last.append(o))
        world.close()
        del pending  # its world is gone: nothing left to release
        self.assertEqual(last, [nl.PATH_CANCELLED], "closing the world cancels what is queued")

    def test_budgets_and_finished_requests_taken_by_the_host(self):
        with nl.World(path_worker_count=0) as world:
            navmesh = gap_level_with_links(world)
            jumper_query, walker_query = nl.PathQuery(navmesh, WEST, EAST, jumper()), nl.PathQuery(navmesh, WEST, EAST, walker())
            self.assertEqual(world.take_finished_paths(), [], "nothing finished yet")
            budget = nl.default_path_budget()
            self.assertEqual((budget.size, budget.max_requests, budget.max_milliseconds, budget.max_search_nodes),
                             (ctypes.sizeof(nl.PathBudget), 0, 0, 0))

            # Budgets: a request is never split, so each limit lets one request through.
            a, b = world.request_path(jumper_query), world.request_path(walker_query)
            self.assertEqual(world.process_paths(max_requests=1), 1)
            self.assertEqual((world.poll_path(a), world.poll_path(b)), (nl.PATH_COMPLETE, nl.PATH_PENDING))
            c, d, e = world.request_path(jumper_query), world.request_path(walker_query), world.request_path(jumper_query)
            self.assertEqual(world.process_paths(max_search_nodes=1), 1, "the request that crosses the limit")
            self.assertEqual((world.poll_path(b), world.poll_path(c)), (nl.PATH_PARTIAL, nl.PATH_PENDING))
            budget.max_search_nodes = 1
            self.assertEqual(world.process_paths(budget=budget), 1)
            self.assertEqual(world.poll_path(d), nl.PATH_PENDING)
            self.assertEqual(world.process_paths(max_milliseconds=1e-6), 1, "a budget of 1 ns: one request")
            self.assertEqual(world.poll_path(e), nl.PATH_PENDING)
            self.assertEqual(world.process_paths(), 1, "no limits: the rest")
            budget.size = 8
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "budget", world.process_paths, budget=budget)

            # Each finished request once, oldest first, with its outcome.
            self.assertEqual(world.take_finished_paths(), [
                (a, nl.PATH_COMPLETE), (b, nl.PATH_PARTIAL), (c, nl.PATH_COMPLETE), (d, nl.PATH_PARTIAL),
                (e, nl.PATH_COMPLETE)])
            self.assertEqual(world.take_finished_paths(), [], "each is taken once")
            finished = nl.FinishedPath(a, nl.PATH_COMPLETE)
            self.assertEqual((finished.ticket, finished.outcome), (a, nl.PATH_COMPLETE))

            # Released tickets are not reported, finished or cancelled; cancelled ones are.
            calls = []
            released = world.request_path(jumper_query, lambda t, o: calls.append(o))
            cancelled, kept, released_later = (world.request_path(walker_query), world.request_path(jumper_query),
                                               world.request_path(walker_query))
            world.release_path(released)
            world.cancel_path(cancelled)
            self.assertEqual(world.process_paths(), 2)
            self.assertEqual(calls, [nl.PATH_CANCELLED], "the released request called back once")
            world.release_path(released_later)
            self.assertEqual(world.take_finished_paths(), [(cancelled, nl.PATH_CANCELLED), (kept, nl.PATH_COMPLETE)])

            # More than the binding takes in one call (16) come back in one list, in order.
            many = [world.request_path(jumper_query if i % 2 == 0 else walker_query) for i in range(40)]
            self.assertEqual(world.process_paths(), 40)
            self.assertEqual(world.take_finished_paths(),
                             [(t, nl.PATH_COMPLETE if i % 2 == 0 else nl.PATH_PARTIAL) for i, t in enumerate(many)])

            # The raw call: the library reads the element size from out_finished[0].size; a refusal loses nothing.
            raw = world.request_path(jumper_query)
            world.process_paths()
            out = (nl.PathFinished * 2)()
            count, remaining = ctypes.c_uint32(99), ctypes.c_uint32(99)
            status = nl.lib.nl_path_take_finished(world.pointer, out, 2, ctypes.byref(count), ctypes.byref(remaining))
            self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT)
            self.assertIn("out_finished", nl.last_error_message())
            out[0] = nl.nl_path_finished_init()
            self.assertEqual(nl.lib.nl_path_take_finished(world.pointer, out, 2, ctypes.byref(count), ctypes.byref(remaining)),
                             nl.STATUS_SUCCESS)
            self.assertEqual((count.value, remaining.value, out[0].ticket, out[0].outcome),
                             (1, 0, raw, nl.PATH_COMPLETE))
            self.assertIsNotNone(out[0].user, "the request's user: the binding's key to its completion")

    def test_invalid_requests(self):
        with nl.World(path_worker_count=0) as world:
            navmesh = gap_level_with_links(world)
            calls = []
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_request", world.request_path,
                             nl.PathQuery(nl.NavmeshId(), WEST, EAST, walker()), lambda t, o: calls.append(o))
            negative = jumper()
            negative.max_jump_distance = -1
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "max_jump_distance", world.request_path,
                             nl.PathQuery(navmesh, WEST, EAST, negative))
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "start", world.find_path,
                             nl.PathQuery(navmesh, (float("nan"), 0, 0), EAST, walker()))
            world.process_paths()
            self.assertTrue(not calls and world.path_queue_stats().submitted == 0)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_cancel", world.cancel_path, nl.PathTicket())
            status = nl.lib.nl_path_get_queue_stats(world.pointer, None)
            self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT)


class AgentTest(NavLinkTestCase):
    """Agents on the bridge level: a jumper takes a generated jump across the gap while a walker goes round
    by the bridge, as the states read in bulk and the step's events say; bad input refused."""
    DT = 1.0 / 30.0
    MAX_STEPS = 30 * 20

    @staticmethod
    def add_agent(world, navmesh, x, z, jump, user_data):
        d = nl.default_agent_def()
        d.navmesh = navmesh
        d.position = nl.Vec3(x, 0, z)
        d.capabilities.radius = 0.3
        d.capabilities.max_jump_distance = jump
        d.capabilities.max_jump_height = 1.0 if jump > 0 else 0.0
        d.user_data = user_data
        return world.add_agent(d)

    @staticmethod
    def is_subsequence(expected, actual):
        """Every item of expected occurs in actual, in that order (others may come between)."""
        items = iter(actual)
        return all(any(item == want for item in items) for want in expected)

    def test_defaults(self):
        d = nl.default_agent_def()
        self.assertEqual(d.size, ctypes.sizeof(nl.AgentDef))
        self.assertEqual((d.height, d.max_speed, d.max_acceleration, d.takeoff_speed, d.avoidance), (2, 3.5, 8, 0, 1))
        self.assertEqual(d.give_up_seconds, 0)
        self.assertEqual((nl.AGENT_EVENT_WAITING, nl.AGENT_REASON_CROWD), (7, 8))
        self.assertAlmostEqual(d.gravity, 9.81, places=5)
        self.assertTrue(d.navmesh.is_null and d.capabilities.max_jump_distance == 0)
        self.assertAlmostEqual(d.capabilities.radius, 0.6, places=6)
        self.assertEqual(nl.lib.nl_default_world_def().agent_paths_per_step, 32)

    def test_walker_goes_round_and_jumper_jumps(self):
        with nl.World() as world:
            navmesh = add_bridge_level(world)
            self.assertTrue(any(link.kind == nl.LINK_JUMP for link in world.links(navmesh)), "jump links across the gap")
            walker_id = self.add_agent(world, navmesh, 1, 2, 0.0, 11)
            jumper_id = self.add_agent(world, navmesh, 1, 3, 3.0, 22)
            self.assertTrue(walker_id != jumper_id and world.is_agent_valid(walker_id))
            self.assertEqual(world.agent_info(walker_id).state, nl.AGENT_IDLE)
            jumper_states = [world.agent_info(jumper_id).state]
            world.set_agent_destination(walker_id, (9, 0, 2))
            world.set_agent_destination(jumper_id, (9, 0, 3))
            jumper_states.append(world.agent_info(jumper_id).state)

            events = []
            walker_corners = jumper_corners = trajectory = in_flight = None
            walker_max_z = 0.0
            for _ in range(self.MAX_STEPS):
                if sum(e.kind == nl.AGENT_EVENT_ARRIVED for e in events) == 2:
                    break
                world.step(self.DT)
                step_events = world.agent_events()
                if any(e.kind == nl.AGENT_EVENT_PATH_READY for e in step_events):
                    walker_corners, jumper_corners = world.agent_corners(walker_id), world.agent_corners(jumper_id)
                events += step_events
                infos = world.agents()
                self.assertEqual(len(infos), 2, "both agents listed after every step")
                for info in infos:
                    if info.id == walker_id:
                        walker_max_z = max(walker_max_z, info.position[2])
                    elif info.id == jumper_id:
                        if info.state != jumper_states[-1]:
                            jumper_states.append(info.state)
                        if info.state == nl.AGENT_JUMPING:
                            in_flight = info
                            if trajectory is None:
                                trajectory = world.agent_trajectory(jumper_id)

            for e in events:
                self.assertEqual(e.size, ctypes.sizeof(nl.AgentEvent))
                self.assertEqual(e.user_data, 11 if e.agent == walker_id else 22)
            ready = [e for e in events if e.kind == nl.AGENT_EVENT_PATH_READY]
            self.assertEqual([e.reason for e in ready], [nl.AGENT_REASON_DESTINATION_SET] * 2)
            self.assertEqual(sum(e.kind == nl.AGENT_EVENT_ARRIVED for e in events), 2)
            self.assertEqual([world.agent_info(a).state for a in (walker_id, jumper_id)], [nl.AGENT_ARRIVED] * 2)

            # The walker takes no link: round by the bridge.
            self.assertFalse(any(e.agent == walker_id and e.kind == nl.AGENT_EVENT_LINK_STARTED for e in events))
            self.assertGreater(walker_max_z, 8)
            self.assertTrue(len(walker_corners) >= 2 and all(p.segment == nl.SEGMENT_WALK for p in walker_corners))
            self.assertEqual(sum(p.segment == nl.LINK_JUMP for p in jumper_corners), 1)

            # The jumper starts and finishes one generated jump.
            started = [e for e in events if e.agent == jumper_id and e.kind == nl.AGENT_EVENT_LINK_STARTED]
            finished = [e for e in events if e.agent == jumper_id and e.kind == nl.AGENT_EVENT_LINK_FINISHED]
            self.assertTrue(len(started) == 1 and len(finished) == 1 and started[0].link == finished[0].link)
            jump = world.link(started[0].link)
            self.assertTrue(jump.kind == nl.LINK_JUMP and jump.generated == 1)
            expected = [nl.AGENT_IDLE, nl.AGENT_WAITING, nl.AGENT_WALKING, nl.AGENT_JUMPING, nl.AGENT_WALKING,
                        nl.AGENT_ARRIVED]
            self.assertTrue(self.is_subsequence(expected, jumper_states), jumper_states)

            # Its trajectory, read in the air.
            self.assertIsNotNone(trajectory, "a trajectory while jumping")
            t = trajectory
            self.assertTrue(t.kind == nl.TRAJECTORY_ARC and t.link == started[0].link)
            self.assertTrue(t.duration > 0 and 0 <= t.elapsed <= t.duration, (t.duration, t.elapsed))
            self.assertGreater(t.apex[1], max(getattr(t, "from")[1], t.to[1]))
            self.assertEqual((list(t.points[0]), list(t.points[3])), (list(getattr(t, "from")), list(t.to)))
            self.assertTrue(in_flight.link == t.link and 0 <= in_flight.link_progress <= 1)

            self.assertIsNone(world.agent_trajectory(jumper_id), "no trajectory on the ground")
            self.assertLessEqual(len(world.agent_corners(walker_id)), 1, "an arrived agent has no corners left")

    def test_a_ferry_carries_walkers_across_a_chasm(self):
        """tests/core/world/surface_tests.cpp's ferry through the ABI: two walkers wait at the near ledge's gangway for
        the shuttle, ride it across (info.navmesh: its deck; info.carrier: the shuttle; carrier_position: in the
        shuttle's space), and get off onto the far ledge by the other gangway."""
        with nl.World() as world:
            add_box(world, FERRY_NEAR_LO, FERRY_NEAR_HI)
            add_box(world, FERRY_FAR_LO, FERRY_FAR_HI)
            shuttle = add_box(world, PLATFORM_LO, PLATFORM_HI, flags=nl.MESH_MOVABLE, transform=platform_at(FERRY_FAR_DOCK))
            agent = nl.default_agent_type()
            agent.radius = 0.3
            ledges = world.add_navmesh(FERRY_LEDGES, list(range(8)), [4, 4], agent_type=agent)
            deck = world.add_navmesh(PLATFORM_TOP, [0, 1, 2, 3], [4], agent_type=agent, carrier=shuttle)

            def gangway(navmesh, start, landing, end):
                d = nl.default_link_def()  # NL_LINK_MANUAL, tolerance 0.25
                d.start, d.end, d.landing_navmesh = start, end, landing
                d.requirements_as_given = 1  # requirements zero: a gap of 0, walked, not jumped
                self.assertEqual((d.kind, d.requirements.gap), (nl.LINK_MANUAL, 0))
                return world.add_link(navmesh, d)

            leave = gangway(deck, (15.4, 0, 3), ledges, (16.6, 0, 3))  # placed docked at the far ledge
            world.set_mesh_transform(shuttle, platform_at(FERRY_NEAR_DOCK))
            board = gangway(ledges, (5.6, 0, 3), deck, (6.6, 0, 3))  # placed docked at the near ledge
            self.assertTrue(world.link(leave).holds == 0 and world.link(board).holds == 1)

            walkers = []
            for z in (2, 4):
                d = nl.default_agent_def()
                d.navmesh, d.position = ledges, nl.Vec3(2, 0, z)
                d.capabilities.radius = 0.3
                walkers.append(world.add_agent(d))
                world.set_agent_destination(walkers[-1], FERRY_GOAL)
            start = world.agent_info(walkers[0])
            self.assertEqual((start.navmesh, start.carrier.is_null), (ledges, True), "standing on the near ledge")
            self.assertEqual(list(start.carrier_position), list(start.position))

            t = 4.0  # the shuttle has just left: the first to reach the gangway waits for it
            arrived, waited, riding, taken, failed = {}, 0, 0, [], []
            for _ in range(90 * 30):
                if len(arrived) == len(walkers):
                    break
                t += self.DT
                x = ferry_x(t)
                world.set_mesh_transform(shuttle, platform_at(x))
                world.step(self.DT)
                events = world.agent_events()
                taken += [(e.agent, e.link) for e in events if e.kind == nl.AGENT_EVENT_LINK_STARTED]
                failed += [(e.agent, e.reason) for e in events if e.kind == nl.AGENT_EVENT_FAILED]
                for info in world.agents():
                    waited += info.state == nl.AGENT_WAITING and info.link == board
                    self.assertIn(info.navmesh, (ledges, deck))
                    if info.state in (nl.AGENT_JUMPING, nl.AGENT_FALLING, nl.AGENT_TRAVERSING):
                        # In the air over a cross link (both gangways are): flown in the world.
                        self.assertLess(distance(info.carrier_position, info.position), 1e-3, "in the air")
                    elif info.navmesh == deck:
                        # On the deck: it rides the shuttle, whose centre is at (x, 0, 3), unturned.
                        riding += 1
                        self.assertEqual(info.carrier, shuttle, "on the deck, riding the shuttle")
                        self.assertLess(distance(info.carrier_position, (info.position[0] - x, info.position[1],
                                                                         info.position[2] - 3)), 1e-3,
                                        "on the shuttle: %s at %s with its centre at x = %.3f"
                                        % (list(info.carrier_position), list(info.position), x))
                    else:
                        self.assertTrue(info.carrier.is_null, "the ledges ride nothing")
                        self.assertLess(distance(info.carrier_position, info.position), 1e-3, "on no carrier")
                for e in events:
                    if e.kind == nl.AGENT_EVENT_ARRIVED:
                        info = world.agent_info(e.agent)
                        arrived[e.agent] = (info.navmesh, info.carrier.is_null, info.position)

            self.assertEqual(failed, [])
            self.assertEqual(set(arrived), set(walkers), "both arrived by t = %.1f s" % t)
            self.assertGreater(waited, 0, "an agent waited at the gangway for the shuttle (WAITING, info.link)")
            self.assertGreater(riding, 0, "an agent stood on the shuttle's deck (info.navmesh, info.carrier)")
            for walker_id in walkers:
                self.assertIn((walker_id, board), taken, "boarded by the near gangway")
                self.assertIn((walker_id, leave), taken, "got off by the far gangway")
                navmesh, no_carrier, position = arrived[walker_id]
                self.assertTrue(navmesh == ledges and no_carrier, "arrived on the far ledge, on no carrier")
                self.assertLess(horizontal(position, FERRY_GOAL), 1.5, list(position))  # two bodies share the goal
                info = world.agent_info(walker_id)
                self.assertEqual((info.state, info.navmesh, info.carrier.is_null), (nl.AGENT_ARRIVED, ledges, True))

    def test_bad_input(self):
        self.assertFails(nl.STATUS_INVALID_ARGUMENT, "agent_paths_per_step", nl.World, agent_paths_per_step=0)
        with nl.World(worker_count=1, agent_paths_per_step=1) as world:
            navmesh = add_bridge_level(world)
            agent = self.add_agent(world, navmesh, 1, 2, 0.0, 0)
            over_the_gap = (5, 0, 2)
            off = nl.default_agent_def()
            off.navmesh, off.position = navmesh, nl.Vec3(*over_the_gap)
            self.assertFails(nl.STATUS_NOT_FOUND, "def->position is not on the navmesh", world.add_agent, off)
            self.assertFails(nl.STATUS_NOT_FOUND, "nearest navmesh point", world.set_agent_destination, agent, over_the_gap)
            self.assertEqual(world.agent_info(agent).has_destination, 0, "a refused destination is not kept")
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "point", world.set_agent_destination, agent, (math.nan, 0, 0))
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "dt", world.step, math.nan)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "max_speed", world.set_agent_speed, agent, -1, 1)
            nan_radius = walker()
            nan_radius.radius = math.nan
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "radius", world.set_agent_capabilities, agent, nan_radius)

            # A raw call must set the element size of its output array, as in C.
            infos, count = (nl.AgentInfo * 1)(), ctypes.c_uint32()
            status = nl.lib.nl_world_get_agents(world.pointer, infos, 1, ctypes.byref(count))
            self.assertTrue(nl.failed(status) and status & nl.STATUS_INVALID_ARGUMENT, hex(status))

            # Its navmesh removed: the agent fails, with its event.
            world.set_agent_destination(agent, (3, 0, 5))
            world.step(0.1)
            world.remove_navmesh(navmesh)
            world.step(0.1)
            events = world.agent_events()
            self.assertEqual([(e.kind, e.reason) for e in events], [(nl.AGENT_EVENT_FAILED, nl.AGENT_REASON_NAVMESH_REMOVED)])
            self.assertEqual(world.agent_info(agent).state, nl.AGENT_FAILED)

            # A removed agent's id is stale everywhere.
            world.remove_agent(agent)
            self.assertTrue(not world.is_agent_valid(agent) and world.agents() == [])
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_agent_set_destination", world.set_agent_destination, agent, (3, 0, 5))
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_agent_get_info", world.agent_info, agent)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_agent_get_trajectory", world.agent_trajectory, agent)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_agent_remove", world.remove_agent, agent)


class ReadableTest(NavLinkTestCase):
    """What the binding gives back reads as a new user would guess (issue 33, item 8): states, reasons, kinds
    and outcomes are IntEnums equal to the old constants, and results print their names and figures."""

    def test_kinds_are_enums_equal_to_the_constants(self):
        for kind, prefix in ((nl.AgentState, "AGENT_"), (nl.AgentReason, "AGENT_REASON_"),
                             (nl.AgentEventKind, "AGENT_EVENT_"), (nl.SegmentKind, "SEGMENT_"),
                             (nl.LinkKind, "LINK_"), (nl.TrajectoryKind, "TRAJECTORY_"), (nl.PathOutcome, "PATH_")):
            self.assertTrue(issubclass(kind, enum.IntEnum), kind)
            for member in kind:
                if kind is nl.SegmentKind and member.name != "WALK":
                    self.assertEqual(member, getattr(nl, "LINK_" + member.name), "a segment is a link's kind")
                    continue
                self.assertIs(getattr(nl, prefix + member.name), member, "the constant is the member")
        self.assertEqual((nl.AGENT_ARRIVED, nl.AGENT_REASON_CROWD, nl.AGENT_EVENT_WAITING, nl.LINK_MANUAL), (6, 8, 7, 3))
        self.assertEqual(nl.LINK_FIRST_PLUGIN_KIND, 256)
        # A value this module has no name for (a plugin's link kind, a newer library's state) stays a number.
        self.assertIs(type(nl.PathPoint(segment=300).segment), int)
        self.assertIs(type(nl.AgentInfo(state=99).state), int)
        link = nl.Link()
        link.kind = nl.LINK_DROP
        self.assertIs(link.kind, nl.LinkKind.DROP)
        self.assertEqual((nl.Link.kind.offset, nl.Link.kind.size), (4, 4), "the field keeps its layout")

    def test_values_returned_are_enums(self):
        with nl.World() as world:
            navmesh = gap_level_with_links(world)
            path = world.find_path(nl.PathQuery(navmesh, WEST, EAST, jumper()))
            self.assertIs(path.outcome, nl.PathOutcome.COMPLETE)
            self.assertIs(path.info.outcome, nl.PathOutcome.COMPLETE)
            self.assertEqual([p.segment for p in path.points if p.segment != nl.SEGMENT_WALK], [nl.SegmentKind.JUMP])
            self.assertTrue(all(type(p.segment) is nl.SegmentKind for p in path.points))
            self.assertTrue(all(type(link.kind) is nl.LinkKind for link in world.links(navmesh)))

            d = nl.default_agent_def()
            d.navmesh, d.position, d.capabilities = navmesh, nl.Vec3(*WEST), jumper()
            agent = world.add_agent(d)
            self.assertIs(world.agent_info(agent).state, nl.AgentState.IDLE)
            self.assertIs(world.agent_info(agent).reason, nl.AgentReason.NONE)
            world.set_agent_destination(agent, EAST)
            events, states, trajectories = [], set(), set()
            for _ in range(30 * 20):
                world.step(1 / 30)
                events += world.agent_events()
                states |= {info.state for info in world.agents()}
                trajectory = world.agent_trajectory(agent)
                if trajectory is not None:
                    trajectories.add(trajectory.kind)
                if world.agent_info(agent).state == nl.AGENT_ARRIVED:
                    break
            self.assertIs(world.agent_info(agent).state, nl.AgentState.ARRIVED)
            self.assertTrue(states and all(type(s) is nl.AgentState for s in states), states)
            self.assertIn(nl.AgentState.JUMPING, states)
            self.assertTrue(events and all(type(e.kind) is nl.AgentEventKind and type(e.reason) is nl.AgentReason
                                           for e in events), events)
            self.assertEqual((events[0].kind, events[0].reason),
                             (nl.AgentEventKind.PATH_READY, nl.AgentReason.DESTINATION_SET))
            self.assertIn(nl.AgentEventKind.LINK_STARTED, [e.kind for e in events])
            self.assertEqual(trajectories, {nl.TrajectoryKind.ARC})
            self.assertTrue(all(type(p.segment) is nl.SegmentKind for p in world.agent_corners(agent)))
            finished = world.request_path(nl.PathQuery(navmesh, WEST, EAST, jumper()))
            finished.wait()
            self.assertTrue(all(type(f.outcome) is nl.PathOutcome for f in world.take_finished_paths()))
            finished.release()

    def test_results_print_readably(self):
        with nl.World() as world:
            navmesh = gap_level_with_links(world)
            path = world.find_path(nl.PathQuery(navmesh, WEST, EAST, jumper()))
            self.assertRegex(repr(path), r"^PathResult\(outcome=COMPLETE, length=12\.\d\d m, points=%d, links=1\)$"
                             % len(path.points))
            self.assertEqual((path.length, path.cost, path.links_used, path.nodes_visited, path.status),
                             (path.info.length, path.info.cost, 1, path.info.nodes_visited, nl.STATUS_SUCCESS))
            self.assertFalse(path.out_of_nodes)
            self.assertEqual((path.start, path.goal), (tuple(path.info.start), tuple(path.info.goal)))
            self.assertEqual(path.positions, [tuple(p.position) for p in path.points])
            self.assertLess(horizontal(path.positions[-1], EAST), 0.01)
            walked = world.find_path(nl.PathQuery(navmesh, WEST, EAST, walker()))
            self.assertRegex(repr(walked), r"^PathResult\(outcome=PARTIAL, length=\d+\.\d\d m, points=\d+, links=0\)$")
            jump = next(p for p in path.points if p.segment == nl.LINK_JUMP)
            self.assertRegex(repr(jump), r"^PathPoint\(position=\(-[\d.]+, [-\d.e]+, [-\d.e]+\), polygon=\d+, "
                                         r"segment=JUMP, link=LinkId\(index=\d+, revision=1\), apex=\(.*\), reversed=0, "
                                         r"carrier_position=\(.*\)\)$")
            self.assertNotIn("size=", repr(jump))
            self.assertNotIn("reserved", repr(jump))

            d = nl.default_agent_def()
            d.navmesh, d.position = navmesh, nl.Vec3(*WEST)
            info = world.agent_info(world.add_agent(d))
            self.assertTrue(repr(info).startswith("AgentInfo(state=IDLE, id=AgentId(index=0, revision=1), position=(-6, "),
                            repr(info))
            self.assertIn("reason=NONE", repr(info))
            self.assertIn("navmesh=NavmeshId(index=0, revision=1), carrier=MeshId(null)", repr(info))
            self.assertEqual(repr(nl.LinkId()), "LinkId(null)")
            world.remove_agent(info.id)
            again = world.add_agent(d)
            self.assertEqual((repr(again), again.slot_index), ("AgentId(index=0, revision=2)", 0), "the slot reused")
            near = world.find_nearest(navmesh, [EAST], (1, 2, 1))[0]
            self.assertRegex(repr(near), r"^NavPoint\(point=\(6, [\d.]+, 0\), distance=[\d.]+, polygon=\d+, found=1, "
                                         r"beyond_box=0\)$")
            self.assertEqual(repr(nl.MeshDef()).split(", ")[0], "MeshDef(vertices=NULL")
            self.assertIn("transform=NULL", repr(nl.MeshDef()))


class PluginTest(NavLinkTestCase):
    # plugin.h: the strings a plugin hands over are static storage. Class constants live as long as the
    # program, and ctypes points a c_char_p field at the bytes object's own buffer.
    NAME = b"python-roof"
    VERSION = b"1.0"
    DESCRIPTION = b"one square over the whole level"
    NO_TRIANGLES = b"python-roof: the level has no triangles"
    USED = b'{"at": "the highest vertex"}'

    def test_plugins(self):
        """A navmesh builder written in Python: one square over the level's bounds, at its highest vertex."""
        @nl.NavmeshBuildFn
        def build(state, host, build_def, sink, sink_context):
            host = host.contents
            vertex_count, triangle_count = ctypes.c_uint32(), ctypes.c_uint32()
            status = host.get_level_triangles(host.context, None, 0, ctypes.byref(vertex_count), None, 0,
                                              ctypes.byref(triangle_count))
            if nl.failed(status):
                return status
            if triangle_count.value == 0:
                host.set_error(host.context, self.NO_TRIANGLES)
                return nl.STATUS_FAILURE | nl.STATUS_NOT_FOUND
            v = (ctypes.c_float * (3 * vertex_count.value))()
            t = (ctypes.c_uint32 * (3 * triangle_count.value))()
            status = host.get_level_triangles(host.context, v, vertex_count, ctypes.byref(vertex_count), t,
                                              triangle_count, ctypes.byref(triangle_count))
            if nl.failed(status):
                return status
            xs, ys, zs = v[0::3], v[1::3], v[2::3]
            lo, hi, top = (min(xs), min(zs)), (max(xs), max(zs)), max(ys)
            quad = nl._floats([lo[0], top, lo[1], lo[0], top, hi[1], hi[0], top, hi[1], hi[0], top, lo[1]])
            square, corners = (ctypes.c_uint32 * 4)(0, 1, 2, 3), (ctypes.c_uint8 * 1)(4)
            navmesh = nl.lib.nl_default_navmesh_def()
            navmesh.vertices, navmesh.vertex_count = ctypes.cast(quad, ctypes.POINTER(ctypes.c_float)), 4
            navmesh.indices = ctypes.cast(square, ctypes.POINTER(ctypes.c_uint32))
            navmesh.polygon_vertex_counts = ctypes.cast(corners, ctypes.POINTER(ctypes.c_uint8))
            navmesh.polygon_count = 1
            navmesh.agent_type = build_def.contents.agent_type
            if host.size >= ctypes.sizeof(nl.PluginHost):  # a host that keeps what a build used
                status = host.record_build_settings(host.context, self.USED, len(self.USED))
                if nl.failed(status):
                    return status
            return sink(sink_context, ctypes.byref(navmesh))

        @nl.PluginEntryFn
        def entry(host_abi_version, host, info):
            if host_abi_version < 1:
                return nl.STATUS_FAILURE | nl.STATUS_VERSION_MISMATCH
            info = info.contents
            info.abi_version = 1
            info.name, info.version, info.description = PluginTest.NAME, PluginTest.VERSION, PluginTest.DESCRIPTION
            info.kinds = nl.PLUGIN_NAVMESH_BUILDER
            info.navmesh_builder.build = build
            return nl.STATUS_SUCCESS

        with nl.World() as world:
            builtin = world.plugins()
            recast = world.plugin_description(builtin[0])
            self.assertTrue(recast["name"] == "recast" and recast["builtin"])
            roof = world.register_plugin(entry)
            mine = world.plugin_description(roof)
            self.assertEqual((mine["name"], mine["builtin"], mine["version"], mine["kinds"]),
                             ("python-roof", False, "1.0", nl.PLUGIN_NAVMESH_BUILDER))
            self.assertEqual(len(world.plugins()), len(builtin) + 1)
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "python-roof", world.register_plugin, entry)
            self.assertFails(nl.STATUS_NOT_FOUND, self.NO_TRIANGLES.decode(), world.build_navmesh, builder="python-roof")
            world.add_mesh([0, 0, 0, 0, 0, 4, 4, 0.5, 4], [0, 1, 2])
            navmesh = world.build_navmesh(builder="python-roof")
            info = world.navmesh_info(navmesh)
            self.assertEqual((info.polygon_count, info.bounds_max[1], info.bounds_max[0]), (1, 0.5, 4))
            made_for = json.loads(nl.describe_navmesh_file(world.save_navmesh(navmesh))[1])
            self.assertEqual((made_for["builder"], made_for["builder_settings"]), ("python-roof", {"at": "the highest vertex"}))
            self.assertFails(nl.STATUS_NOT_FOUND, "nl_plugin_load", world.load_plugin, "/no/such/plugin.so")


# Debian's python3-numpy (scripts/setup.sh) is installed for /usr/bin/python3; a Python of the same version
# built elsewhere (pyenv's, which ctest may run) loads the same extension modules.
DEBIAN_DIST_PACKAGES = "/usr/lib/python3/dist-packages"


def numpy_or_skip(test):
    try:
        import numpy
        return numpy
    except ImportError:
        pass
    if os.path.isdir(os.path.join(DEBIAN_DIST_PACKAGES, "numpy")) and DEBIAN_DIST_PACKAGES not in sys.path:
        sys.path.append(DEBIAN_DIST_PACKAGES)  # last: it shadows nothing this Python has itself
        try:
            import numpy
            return numpy
        except Exception:  # built for another Python version
            sys.path.remove(DEBIAN_DIST_PACKAGES)
            for name in [m for m in sys.modules if m == "numpy" or m.startswith("numpy.")]:
                del sys.modules[name]
    test.skipTest("numpy is not installed for %s (scripts/setup.sh installs Debian's python3-numpy): the numpy "
                  "cases are skipped (array.array and memoryview cover the same paths)" % sys.executable)


class BufferTest(NavLinkTestCase):
    """Geometry from lists and from buffers gives the same meshes and navmeshes; writable buffers are read in
    place, read-only ones copied once; wrong ones are refused naming the argument, before the library."""

    def mesh_summary(self, world, mesh):
        info = world.mesh_info(mesh)
        return (info.vertex_count, info.triangle_count, tuple(info.bounds_min), tuple(info.bounds_max))

    def test_a_mesh_from_each_kind_of_buffer(self):
        lo, hi = (-1, -2, -3), (4, 5, 6)
        vertices, indices = box_vertices(lo, hi), BOX_INDICES
        floats, uints = array.array("f", vertices), array.array("I", indices)
        rows_of_four = array.array("f", [c for k in range(8) for c in vertices[3 * k:3 * k + 3] + [99.0]])
        inputs = {
            "array.array": (floats, uints),
            "memoryview": (memoryview(floats), memoryview(uints)),
            "memoryview of rows (n, 3)": (memoryview(floats).cast("B").cast("f", (8, 3)),
                                          memoryview(uints).cast("B").cast("I", (12, 3))),
            "rows of 4, x y z first (stride 16)": (memoryview(rows_of_four).cast("B").cast("f", (8, 4)), uints),
            "bytes (read-only)": (floats.tobytes(), uints.tobytes()),
            "bytearray": (bytearray(floats.tobytes()), bytearray(uints.tobytes())),
            "int32 indices": (floats, array.array("i", indices)),
            "tuples": (tuple(vertices), tuple(indices)),
        }
        with nl.World() as world:
            expected = self.mesh_summary(world, world.add_mesh(vertices, indices))
            self.assertEqual(expected[:2], (8, 12))
            self.assertNear(expected[2] + expected[3], lo + hi, "the box's bounds")
            for kind, (v, i) in inputs.items():
                self.assertEqual(self.mesh_summary(world, world.add_mesh(v, i)), expected, kind)
            moved = world.add_mesh(floats, uints, transform=array.array("f", RAFT_MOVED))
            # RAFT_MOVED: x goes to -z, z to x, then 10 m along x.
            self.assertNear(world.mesh_info(moved).bounds_min, (10 + lo[2], lo[1], -hi[0]), "a transform from a buffer")

    def test_writable_buffers_are_read_in_place(self):
        floats = array.array("f", FLOOR)
        given = nl._c_array("vertices", floats, ctypes.c_float, group=3)
        self.assertEqual(ctypes.addressof(given.items), floats.buffer_info()[0], "no copy of a writable buffer")
        frozen = floats.tobytes()
        copied = nl._c_array("vertices", frozen, ctypes.c_float, group=3)
        self.assertEqual(bytes(copied.items), frozen, "a read-only buffer is copied whole")
        odd = bytearray(1) + bytearray(frozen)
        shifted = nl._c_array("vertices", memoryview(odd)[1:], ctypes.c_float, group=3)
        self.assertEqual(ctypes.addressof(shifted.items) % ctypes.alignment(ctypes.c_float), 0, "aligned for C")
        self.assertEqual(list(shifted.items), [float(c) for c in FLOOR])

    def test_a_navmesh_from_buffers(self):
        vertices, indices, corner_counts = bridge_navmesh_polygons()
        areas = [3, 1, 4, 1, 5]
        with nl.World() as world:
            from_lists = world.add_navmesh(vertices, indices, corner_counts, areas=areas, agent_type=bridge_agent_type())
            from_buffers = world.add_navmesh(array.array("f", vertices), array.array("I", indices),
                                             bytes(corner_counts), areas=bytearray(areas), agent_type=bridge_agent_type())
            for navmesh in (from_lists, from_buffers):
                info = world.navmesh_info(navmesh)
                self.assertEqual(info.polygon_count, 5)
                self.assertEqual(sorted(world.polygon(navmesh, p).area for p in range(info.polygon_count)),
                                 sorted(areas))
            self.assertEqual(world.navmesh_vertices(from_buffers), world.navmesh_vertices(from_lists))
            near = world.find_nearest(from_buffers, array.array("f", [2, 1, 4, 8, 1, 4]), array.array("f", [1, 2, 1]))
            self.assertTrue(all(p.found for p in near) and len(near) == 2)
            self.assertNear(near[1].point, (8, 0, 4), "found through a buffer of points")
            data = world.save_navmesh(from_buffers)
            self.assertEqual(nl.describe_navmesh_file(memoryview(data))[0].polygon_count, 5)
            loaded = world.load_navmesh(bytearray(data))
            self.assertEqual(world.navmesh_info(loaded).polygon_count, 5)
            query = nl.PathQuery(from_buffers, (2, 0, 4), (8, 0, 4), walker())
            query.area_costs = array.array("f", [1, 1, 1, 1, 1, 1])
            self.assertEqual(world.find_path(query).outcome, nl.PATH_COMPLETE)
            query.area_costs = array.array("f", [1, nl.AREA_EXCLUDED, 1, 1, 1, 1])
            self.assertEqual(world.find_path(query).outcome, nl.PATH_PARTIAL, "area 1 (the bridge's end) kept out")

    def test_wrong_buffers_are_refused_naming_the_argument(self):
        floats, uints = array.array("f", FLOOR), array.array("I", QUAD)
        cases = [
            (TypeError, "indices", "integers from 0 to 4294967295", (floats, array.array("d", QUAD))),
            (TypeError, "indices", "integers", (floats, [0, 2, 1.5, 0, 3, 2])),
            (ValueError, "indices", "integers from 0 to 4294967295", (floats, array.array("q", [-1] + QUAD[1:]))),
            (ValueError, "indices", "integers from 0 to 4294967295", (floats, [0, 2, 1, 0, 3, -2])),
            (ValueError, "indices", "integers from 0 to 4294967295", (floats, array.array("q", [2 ** 32] + QUAD[1:]))),
            (TypeError, "vertices", "not str", ("0 0 0", uints)),
            (TypeError, "vertices", "not str", (["0 0 0"], uints)),
            (TypeError, "vertices", "", ([0, 0, "x"], uints)),
            (TypeError, "vertices", "not object", (object(), uints)),
            (ValueError, "vertices", "multiple of 3", (array.array("f", FLOOR[:-1]), uints)),
            (ValueError, "vertices", "multiple of 3", (FLOOR[:-1], QUAD)),
            (ValueError, "vertices", "multiple of 3", (array.array("d", FLOOR[:-1]), QUAD)),
            (ValueError, "indices", "multiple of 3", (floats, array.array("I", QUAD[:-1]))),
            (ValueError, "vertices", "whole number of 4-byte items", (floats.tobytes()[:-2], uints)),
            (ValueError, "vertices", "shape (6, 2)", (memoryview(floats).cast("B").cast("f", (6, 2)), uints)),
            (ValueError, "vertices", "rows of 2 values; rows of 3 or more", ([(0, 0)] * 6, uints)),
            (ValueError, "vertices", "rows of 2 and 3 values", ([(0, 0, 0)] * 3 + [(0, 0)], uints)),
            (ValueError, "indices", "shape (3, 4)", (floats, memoryview(array.array("I", QUAD * 2)).cast("B").cast("I", (3, 4)))),
            (ValueError, "indices", "rows of 2 values; rows of 3 expected", (floats, [(0, 2), (1, 0), (3, 2)])),
        ]
        with nl.World() as world:
            for error, name, part, (v, i) in cases:
                with self.assertRaises(error, msg="%s %s" % (name, part)) as caught:
                    world.add_mesh(v, i)
                self.assertTrue(str(caught.exception).startswith(name + ":"), caught.exception)
                self.assertIn(part, str(caught.exception))
            self.assertFails(nl.STATUS_INVALID_ARGUMENT, "indices", world.add_mesh, floats, array.array("I", [0, 1, 7]))
            with self.assertRaisesRegex(ValueError, "^transform: 15 values, 16 expected"):
                world.add_mesh(floats, uints, transform=RAFT_MOVED[:-1])
            with self.assertRaisesRegex(ValueError, "^destination: 2 values, 3 expected"):
                world.set_agent_destination(nl.AgentId(), (1, 2))
            vertices, indices, corner_counts = bridge_navmesh_polygons()
            with self.assertRaisesRegex(ValueError, "^areas: 4 values, 5 expected"):
                world.add_navmesh(vertices, indices, corner_counts, areas=bytes(4))
            with self.assertRaisesRegex(ValueError, "^indices: %d values, but polygon_vertex_counts adds up to %d" % (
                    len(indices) - 1, sum(corner_counts))):
                world.add_navmesh(vertices, indices[:-1], corner_counts)
            with self.assertRaisesRegex(ValueError, "^polygon_vertex_counts: integers from 0 to 255 expected"):
                world.add_navmesh(vertices, indices, array.array("I", [256] + corner_counts[1:]))
            self.assertEqual(world.meshes(), [], "nothing registered")
            self.assertEqual(world.navmeshes(), [], "nothing added")

    def test_other_numbers_and_nested_points_are_converted(self):
        """Points as [(x, y, z), ...] or [[x, y, z], ...], triangles as rows, and buffers of other numbers
        (doubles, 64- and 16-bit integers, a strided view) are converted once to the C layout rather than
        refused: the same mesh as from flat lists (issue 33, item 8)."""
        lo, hi = (-1, -2, -3), (4, 5, 6)
        vertices, indices = box_vertices(lo, hi), BOX_INDICES
        points = [tuple(vertices[k:k + 3]) for k in range(0, len(vertices), 3)]
        triangles = [indices[k:k + 3] for k in range(0, len(indices), 3)]
        doubles = array.array("d", vertices)
        inputs = {
            "a list of (x, y, z) tuples": (points, indices),
            "a list of [x, y, z] lists, triangles as rows": ([list(p) for p in points], triangles),
            "a tuple of tuples": (tuple(points), tuple(tuple(t) for t in triangles)),
            "rows of 4, x y z first": ([list(p) + [99.0] for p in points], indices),
            "Vec3 rows": ([nl.Vec3(*p) for p in points], indices),
            "array('d')": (doubles, indices),
            "a memoryview of doubles in rows (n, 3)": (memoryview(doubles).cast("B").cast("d", (8, 3)), indices),
            "int64 and uint16 indices": (doubles, array.array("q", indices)),
            "uint16 indices": (vertices, array.array("H", indices)),
            "integer vertices": (array.array("i", vertices), indices),
            "a strided view": (memoryview(array.array("f", [c for v in vertices for c in (v, -7.0)]))[::2], indices),
            "a range of indices": (vertices[:9], range(3)),
            "a generator": ((c for c in vertices), iter(indices)),
        }
        with nl.World() as world:
            expected = self.mesh_summary(world, world.add_mesh(vertices, indices))
            for kind, (v, i) in inputs.items():
                summary = self.mesh_summary(world, world.add_mesh(v, i))
                if kind == "a range of indices":
                    self.assertEqual(summary[:2], (3, 1), kind)
                else:
                    self.assertEqual(summary, expected, kind)
            self.assertEqual(nl._c_array("vertices", [list(p) + [9.0] for p in points], ctypes.c_float, group=3,
                                         wider_rows=True).row, 4, "nested rows of 4 are read with a stride of 4")
            moved = world.add_mesh(points, triangles, transform=array.array("d", RAFT_MOVED))
            self.assertNear(world.mesh_info(moved).bounds_min, (10 + lo[2], lo[1], -hi[0]), "a transform of doubles")

            # A navmesh from nested polygons (rows of any length are read one after the other), points and
            # destinations from doubles.
            flat_vertices, flat_indices, corner_counts = bridge_navmesh_polygons()
            rows = [flat_vertices[k:k + 3] for k in range(0, len(flat_vertices), 3)]
            polygons, start = [], 0
            for n in corner_counts:
                polygons.append(flat_indices[start:start + n])
                start += n
            navmesh = world.add_navmesh(rows, polygons, corner_counts, areas=array.array("q", [3, 1, 4, 1, 5]),
                                        agent_type=bridge_agent_type())
            self.assertEqual(world.navmesh_vertices(navmesh),
                             world.navmesh_vertices(world.add_navmesh(flat_vertices, flat_indices, corner_counts,
                                                                      agent_type=bridge_agent_type())))
            near = world.find_nearest(navmesh, [(2, 1, 4), [8, 1, 4]], array.array("d", [1, 2, 1]))
            self.assertTrue(all(p.found for p in near) and len(near) == 2)
            self.assertNear(near[1].point, (8, 0, 4), "points as a list of rows")
            query = nl.PathQuery(navmesh, array.array("d", (2, 0, 4)), [[8, 0, 4]], walker())
            query.area_costs = array.array("d", [1] * 6)
            self.assertEqual(world.find_path(query).outcome, nl.PATH_COMPLETE)
            with self.assertRaisesRegex(ValueError, "^goal: 2 values, 3 expected"):
                nl.PathQuery(navmesh, (2, 0, 4), (8, 0), walker())
            self.assertEqual(world.segments_blocked([(array.array("d", (-10, 3, 0)), [10.0, 3.0, 0.0])]), [True])
            with self.assertRaisesRegex(ValueError, r"^areas: integers from 0 to 255 expected"):
                world.add_navmesh(rows, polygons, corner_counts, areas=[3, 1, 4, 1, 256])

    def test_numpy_arrays(self):
        numpy = numpy_or_skip(self)
        vertices = numpy.array(box_vertices((0, 0, 0), (1, 1, 1)), dtype=numpy.float32).reshape(8, 3)
        with nl.World() as world:
            for indices in (numpy.array(BOX_INDICES, dtype=numpy.uint32), numpy.array(BOX_INDICES, dtype=numpy.int32)):
                self.assertEqual(world.mesh_info(world.add_mesh(vertices, indices)).triangle_count, 12)
            given = nl._c_array("vertices", vertices, ctypes.c_float, group=3)
            self.assertEqual(ctypes.addressof(given.items), vertices.ctypes.data, "read in place")
            expected = self.mesh_summary(world, world.add_mesh(vertices, BOX_INDICES))
            triangles = numpy.array(BOX_INDICES).reshape(12, 3)  # numpy's default integers: int64
            inputs = {
                "float64 (n, 3), int64 (m, 3)": (vertices.astype(numpy.float64), triangles),
                "float64 flat, uint16": (vertices.astype(numpy.float64).ravel(), triangles.astype(numpy.uint16)),
                "big-endian float32": (vertices.astype(">f4"), triangles),
                "half floats": (vertices.astype(numpy.float16), triangles),
                "Fortran order (strided)": (numpy.asfortranarray(vertices.astype(numpy.float64)), triangles.T.copy().T),
                "a list of numpy rows": (list(vertices.astype(numpy.float64)), list(triangles)),
                "numpy scalars in lists": ([numpy.float64(c) for c in vertices.ravel()],
                                           [numpy.int64(i) for i in BOX_INDICES]),
            }
            for kind, (v, i) in inputs.items():
                self.assertEqual(self.mesh_summary(world, world.add_mesh(v, i)), expected, kind)
            with self.assertRaisesRegex(ValueError, r"^vertices: a buffer of shape \(8, 2\); rows of 3 or more"):
                world.add_mesh(vertices[:, :2], BOX_INDICES)
            with self.assertRaisesRegex(ValueError, "^indices: integers from 0 to 4294967295 expected"):
                world.add_mesh(vertices, -triangles)
            with self.assertRaisesRegex(TypeError, "^indices: integers"):
                world.add_mesh(vertices, triangles.astype(numpy.float64))

            navmesh = gap_level_with_links(world)
            west, east = numpy.array(WEST), numpy.array(EAST)  # float64
            result = world.find_path(nl.PathQuery(navmesh, west, east, jumper()))
            self.assertJumperAcross(world, result)
            near = world.find_nearest(navmesh, numpy.array([WEST, EAST]), numpy.array([1.0, 2.0, 1.0]))
            self.assertTrue(near[1].found and horizontal(near[1].point, EAST) < 0.01, "points from a float64 (n, 3) array")
            d = nl.default_agent_def()
            d.navmesh, d.position = navmesh, nl.Vec3(*west)
            agent = world.add_agent(d)
            world.set_agent_destination(agent, east - numpy.array([3.0, 0.0, 0.0]))
            world.teleport_agent(agent, west + numpy.array([1.0, 0.0, 0.0]))
            self.assertLess(horizontal(world.agent_info(agent).position, (WEST[0] + 1, 0, 0)), 0.01, "a float64 position")


def hold_the_only_worker(test, world, query):
    """A request whose callback holds a one-worker world's path worker until the returned event is set:
    requests queued after it stay pending meanwhile."""
    entered, release = threading.Event(), threading.Event()

    def hold(ticket, outcome):
        entered.set()
        release.wait(30)
    request = world.request_path(query, hold)
    test.assertTrue(entered.wait(30), "the worker took the request")
    return request, release


def thread_count():
    return len(os.listdir("/proc/self/task")) if os.path.isdir("/proc/self/task") else None


class WaitTest(NavLinkTestCase):
    """PathRequest: blocking waits with and without path workers, timeouts, asyncio, release by RAII."""

    def test_wait_with_path_workers(self):
        with nl.World(path_worker_count=1) as world:
            self.assertEqual(world.path_queue_stats().workers, 1)
            navmesh = gap_level_with_links(world)
            jumper_query, walker_query = nl.PathQuery(navmesh, WEST, EAST, jumper()), nl.PathQuery(navmesh, WEST, EAST, walker())
            with world.request_path(jumper_query) as jumped, world.request_path(walker_query) as walked:
                self.assertIs(jumped.wait(), nl.PathOutcome.COMPLETE)
                self.assertEqual(walked.wait(timeout=30), nl.PATH_PARTIAL)
                self.assertJumperAcross(world, jumped.result())
                self.assertWalkerStopsAtGap(walked.result())

            held, release = hold_the_only_worker(self, world, jumper_query)
            with held, world.request_path(jumper_query) as queued:
                started = time.monotonic()
                self.assertIs(queued.wait(timeout=0.2), nl.PathOutcome.PENDING, "timed out behind the held worker")
                self.assertGreaterEqual(time.monotonic() - started, 0.19)
                self.assertIs(queued.wait(0), nl.PathOutcome.PENDING)
                waited = []
                waiter = threading.Thread(target=lambda: waited.append(queued.wait()))
                waiter.start()
                waiter.join(0.3)
                # This thread ran Python while the other was in nl_path_wait: the wait let go of the GIL.
                self.assertTrue(waiter.is_alive() and not waited, "still waiting while the worker is held")
                release.set()
                waiter.join(30)
                self.assertEqual(waited, [nl.PATH_COMPLETE])
                self.assertJumperAcross(world, queued.result())

    def test_wait_without_path_workers_plans_on_the_waiting_thread(self):
        with nl.World(path_worker_count=0) as world:
            navmesh = gap_level_with_links(world)
            planned_on = []
            first = world.request_path(nl.PathQuery(navmesh, WEST, EAST, walker()),
                                       lambda t, o: planned_on.append(("first", threading.get_ident())))
            second = world.request_path(nl.PathQuery(navmesh, WEST, EAST, jumper()),
                                        lambda t, o: planned_on.append(("second", threading.get_ident())))
            self.assertIs(second.wait(0), nl.PathOutcome.PENDING, "timeout 0 only looks")
            outcome = ctypes.c_uint32(99)
            status = nl.lib.nl_path_wait(world.pointer, second, 0, ctypes.byref(outcome))
            self.assertEqual((status, outcome.value), (nl.STATUS_IN_PROGRESS, nl.PATH_PENDING), "the raw call")
            self.assertEqual(world.path_queue_stats().queued, 2, "nothing planned by looking")
            self.assertIs(second.wait(), nl.PathOutcome.COMPLETE)
            me = threading.get_ident()
            self.assertEqual(planned_on, [("first", me), ("second", me)], "oldest first, on the waiting thread")
            self.assertEqual(first.poll(), nl.PATH_PARTIAL)
            self.assertJumperAcross(world, second.result())
            first.release()
            second.release()

    def test_waits_refused(self):
        with nl.World(path_worker_count=0) as world:
            navmesh = gap_level_with_links(world)
            query = nl.PathQuery(navmesh, WEST, EAST, jumper())
            inside = []

            def wait_inside(ticket, outcome):
                try:
                    world.wait_path(ticket, 1)
                except nl.NavLinkError as e:
                    inside.append(e)
            with world.request_path(query, wait_inside) as request:
                request.wait()
            self.assertEqual(len(inside), 1)
            self.assertTrue(inside[0].has(nl.STATUS_INVALID_ARGUMENT), inside[0])
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_wait", request.wait)
            with world.request_path(query) as request:
                for bad in (-1, float("nan")):
                    with self.assertRaisesRegex(ValueError, "^timeout"):
                        request.wait(bad)

    def test_asyncio_awaits_several_requests_at_once(self):
        with nl.World(path_worker_count=1) as world:
            navmesh = gap_level_with_links(world)
            queries = [nl.PathQuery(navmesh, WEST, EAST, jumper() if k % 2 == 0 else walker()) for k in range(6)]
            expected = [nl.PATH_COMPLETE if k % 2 == 0 else nl.PATH_PARTIAL for k in range(6)]
            called_back = []

            async def await_them():
                held, release = hold_the_only_worker(self, world, queries[0])
                requests = [world.request_path(q, lambda t, o: called_back.append(t)) for q in queries]
                threads = thread_count()
                gathering = asyncio.gather(*requests[:3], *(r.wait_async() for r in requests[3:]))
                await asyncio.sleep(0.1)  # the loop runs while the requests wait behind the held worker
                self.assertFalse(gathering.done(), "nothing finished while the worker is held")
                self.assertEqual(thread_count(), threads, "no thread per await")
                release.set()
                outcomes = await asyncio.wait_for(gathering, 30)
                self.assertEqual(sorted(called_back, key=requests.index), requests, "each callback ran before")
                self.assertIs(await requests[0], nl.PathOutcome.COMPLETE, "a finished request awaits at once")
                held.release()
                return requests, outcomes
            requests, outcomes = asyncio.run(await_them())
            self.assertEqual(outcomes, expected)
            self.assertJumperAcross(world, requests[0].result())
            for request in requests:
                request.release()
            self.assertEqual(world.path_queue_stats().unreleased, 0)

    def test_await_without_path_workers_plans_on_the_loop(self):
        """With path_worker_count 0 nobody else plans a queued request: awaiting it plans the queue on the
        loop's thread (nl_path_process), oldest first, one request at a time with the loop running between
        them, instead of waiting for ever (issue 33, item 8)."""
        with nl.World(path_worker_count=0) as world:
            self.assertEqual(world.path_queue_stats().workers, 0)
            navmesh = gap_level_with_links(world)
            planned_on = []
            queries = [nl.PathQuery(navmesh, WEST, EAST, jumper() if k % 2 == 0 else walker()) for k in range(4)]

            async def await_them():
                loop_thread = threading.get_ident()
                ticks = []

                async def tick():
                    while True:
                        ticks.append(world.path_queue_stats().queued)
                        await asyncio.sleep(0)
                ticker = asyncio.ensure_future(tick())
                requests = [world.request_path(q, lambda t, o: planned_on.append((t, threading.get_ident())))
                            for q in queries]
                self.assertEqual(world.path_queue_stats().queued, 4)
                last = await asyncio.wait_for(requests[-1], 10)  # plans the three before it first
                self.assertEqual([t for t, _ in planned_on], requests, "oldest first")
                self.assertTrue(all(thread == loop_thread for _, thread in planned_on), "on the loop's thread")
                self.assertIn(2, ticks, "the loop ran between two requests")
                self.assertIs(await requests[0], nl.PathOutcome.COMPLETE, "already finished: at once")
                more = [world.request_path(q) for q in queries]
                outcomes = await asyncio.wait_for(asyncio.gather(*more), 10)
                for request in more:
                    request.release()
                ticker.cancel()
                return requests, last, outcomes
            requests, last, outcomes = asyncio.run(await_them())
            self.assertIs(last, nl.PathOutcome.PARTIAL)
            self.assertEqual(outcomes, [nl.PATH_COMPLETE, nl.PATH_PARTIAL] * 2)
            self.assertJumperAcross(world, requests[0].result())
            for request in requests:
                request.release()
            self.assertEqual(world.path_queue_stats().unreleased, 0)

    def test_tickets_released_by_with_release_and_drop(self):
        with nl.World(path_worker_count=0) as world:
            navmesh = gap_level_with_links(world)
            query = nl.PathQuery(navmesh, WEST, EAST, jumper())
            calls = []
            with world.request_path(query, lambda t, o: calls.append(o)) as pending:
                self.assertEqual(world.path_queue_stats().unreleased, 1)
                self.assertTrue(pending == pending.ticket and pending.ticket == pending)
                self.assertEqual(hash(pending), hash(pending.ticket))
            self.assertEqual(calls, [nl.PATH_CANCELLED], "leaving `with` released it, cancelling it")
            self.assertEqual(world.path_queue_stats().unreleased, 0)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_poll", pending.poll)
            pending.release()  # once released, release() does nothing

            with self.assertRaises(RuntimeError):
                with world.request_path(query) as request:
                    raise RuntimeError("the block failed")
            self.assertEqual(world.path_queue_stats().unreleased, 0, "released on an exception too")

            dropped_calls = []
            dropped = world.request_path(query, lambda t, o: dropped_calls.append(o))
            ticket = dropped.ticket
            del dropped
            gc.collect()
            self.assertEqual(dropped_calls, [nl.PATH_CANCELLED], "a dropped request is released")
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_poll", world.poll_path, ticket)

            kept = world.request_path(query)
            ticket = kept.detach()
            del kept
            gc.collect()
            self.assertEqual(world.poll_path(ticket), nl.PATH_PENDING, "a detached ticket outlives its request")
            world.release_path(ticket)

            with world.request_path(query) as request:
                world.release_path(request)
            self.assertFails(nl.STATUS_INVALID_HANDLE, "nl_path_release", world.release_path, request)
            self.assertEqual(world.path_queue_stats().unreleased, 0)


def library_lookup_environment(**variables):
    """This process's environment without anything that steers the library lookup, plus `variables`."""
    steering = ("NAVLINK_LIBRARY", "PKG_CONFIG_PATH", "PKG_CONFIG_LIBDIR", "LD_LIBRARY_PATH", "PYTHONPATH")
    environment = {k: v for k, v in os.environ.items() if k not in steering}
    environment.update(variables)
    return environment


def write_navlink_pc(folder, libdir):
    """A navlink.pc whose libdir is `libdir`, as an installed NavLink's is; PKG_CONFIG_PATH and
    PKG_CONFIG_LIBDIR of the returned dict make it the only one pkg-config sees."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "navlink.pc"), "w") as f:
        f.write("libdir=%s\nName: NavLink\nDescription: the library under test\nVersion: %d.%d.%d\n"
                "Libs: -L${libdir} -lnavlink\n" % ((libdir,) + nl.version()))
    return {"PKG_CONFIG_PATH": folder, "PKG_CONFIG_LIBDIR": folder}


PROBE = "import json, navlink; print(json.dumps([navlink.library_path, navlink.__file__, navlink.version()]))"


class PackageTest(unittest.TestCase):
    """Where the module finds libnavlink, and the package pip builds offline from pyproject.toml."""

    @classmethod
    def setUpClass(cls):
        cls.library = os.path.realpath(nl.library_path)
        cls.tmp = tempfile.TemporaryDirectory()
        cls.have_pkg_config = subprocess.run(["sh", "-c", "command -v pkg-config"], capture_output=True).returncode == 0

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def folder(self, name):
        path = os.path.join(self.tmp.name, self.id().rsplit(".", 1)[-1], name)
        os.makedirs(path, exist_ok=True)
        return path

    def linked_library(self, name):
        """A folder holding libnavlink.so.0, a link to the library under test."""
        folder = self.folder(name)
        os.symlink(self.library, os.path.join(folder, "libnavlink.so.0"))
        return folder

    def probe(self, environment, python=sys.executable, source_tree=True):
        if source_tree:
            environment = dict(environment, PYTHONPATH=HERE)
        return subprocess.run([python, "-c", PROBE], capture_output=True, text=True, env=environment,
                              cwd=self.tmp.name, timeout=120)

    def loaded(self, run):
        self.assertEqual(run.returncode, 0, run.stderr)
        return json.loads(run.stdout)

    def test_lookup_order_and_what_a_failed_lookup_says(self):
        if not self.have_pkg_config:
            self.skipTest("pkg-config is not installed (Debian: pkg-config)")
        explicit, by_pkg_config = self.linked_library("explicit"), self.linked_library("pkg-config")
        pc = write_navlink_pc(self.folder("pc"), by_pkg_config)
        explicit_library = os.path.join(explicit, "libnavlink.so.0")
        found = self.loaded(self.probe(library_lookup_environment(NAVLINK_LIBRARY=explicit_library, **pc)))
        self.assertEqual(found[0], explicit_library, "NAVLINK_LIBRARY first")
        self.assertEqual(found[2], list(nl.version()))
        found = self.loaded(self.probe(library_lookup_environment(**pc)))
        self.assertEqual(found[0], os.path.join(by_pkg_config, "libnavlink.so.0"), "then pkg-config's libdir")

        missing = os.path.join(explicit, "no-such-libnavlink.so")
        run = self.probe(library_lookup_environment(NAVLINK_LIBRARY=missing, **pc))
        self.assertNotEqual(run.returncode, 0, "an explicit library that does not load is not replaced")
        self.assertIn("ImportError", run.stderr)
        self.assertIn("NAVLINK_LIBRARY: %s did not load" % missing, run.stderr)

        nothing = write_navlink_pc(self.folder("empty"), self.folder("no-library-here"))
        os.remove(os.path.join(self.folder("empty"), "navlink.pc"))
        installed = [os.path.join(d, n) for d in nl._installed_library_dirs() for n in nl._LIBRARY_FILE_NAMES
                     if os.path.exists(os.path.join(d, n))]
        run = self.probe(library_lookup_environment(**nothing))
        if ctypes.util.find_library("navlink") or installed:
            found = self.loaded(run)
            self.assertNotEqual(found[0], self.library, "an installed NavLink answers: %s" % found[0])
            return
        self.assertNotEqual(run.returncode, 0)
        message = run.stderr[run.stderr.index("ImportError"):]
        for what in ("NAVLINK_LIBRARY: not set", "pkg-config navlink: no navlink.pc", "Package navlink was not found",
                     'ctypes.util.find_library("navlink"): found nothing', "installed: none of libnavlink.so.0",
                     os.path.join(sys.prefix, "lib"), "/usr/local/lib", "cmake --install", "PKG_CONFIG_PATH",
                     "set NAVLINK_LIBRARY"):
            self.assertIn(what, message)
        self.assertLess(message.index("NAVLINK_LIBRARY: not set"), message.index("pkg-config navlink"))
        self.assertLess(message.index("pkg-config navlink"), message.index("ctypes.util.find_library"))
        self.assertLess(message.index("ctypes.util.find_library"), message.index("installed: none"))

    def pip_or_skip(self, python=sys.executable):
        if subprocess.run([python, "-m", "pip", "--version"], capture_output=True).returncode != 0:
            self.skipTest("no pip for %s (Debian: python3-pip)" % python)

    def pip_install(self, *arguments, python_options=()):
        run = subprocess.run([sys.executable, "-m", "pip"] + list(python_options) +
                             ["install", "--no-index", "--no-build-isolation", "--no-cache-dir",
                              "--disable-pip-version-check", "--quiet"] + list(arguments) + [HERE],
                             capture_output=True, text=True, timeout=300, cwd=self.tmp.name,
                             env=library_lookup_environment(PIP_NO_INPUT="1"))
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)

    def test_pip_install_offline_into_a_folder_found_through_pkg_config(self):
        self.pip_or_skip()
        if not self.have_pkg_config:
            self.skipTest("pkg-config is not installed (Debian: pkg-config)")
        site = self.folder("site")
        self.pip_install("--target", site)
        package = os.path.join(site, "navlink")
        self.assertTrue(os.path.isfile(os.path.join(package, "py.typed")), "the PEP 561 marker ships")
        with open(os.path.join(package, "__init__.py"), "rb") as installed, open(nl.__file__, "rb") as source:
            self.assertEqual(installed.read(), source.read(), "the package is navlink.py")
        pc = write_navlink_pc(self.folder("pc"), os.path.dirname(self.library))
        found = self.loaded(self.probe(library_lookup_environment(PYTHONPATH=site, **pc), source_tree=False))
        self.assertEqual(found[1], os.path.join(package, "__init__.py"), "the installed package was imported")
        self.assertEqual(os.path.realpath(found[0]), self.library)
        self.assertEqual(found[2], list(nl.version()))

    def test_pip_install_into_a_fresh_virtual_environment(self):
        """No variable at all: NavLink installed into the environment's prefix (cmake --install --prefix),
        as the lookup's installed places have it. PKG_CONFIG_LIBDIR points at an empty folder only so that
        a NavLink installed on this machine cannot answer instead."""
        self.pip_or_skip()
        environment = self.folder("venv")
        created = subprocess.run([sys.executable, "-m", "venv", "--without-pip", environment], capture_output=True,
                                 text=True, timeout=120)
        if created.returncode != 0:
            self.skipTest("no venv for %s: %s" % (sys.executable, created.stderr.strip()))
        python = os.path.join(environment, "bin", "python")
        self.pip_install(python_options=("--python", python))  # pip 22.3+: installs for that interpreter
        prefix = subprocess.run([python, "-c", "import sys; print(sys.prefix)"], capture_output=True, text=True)
        libdir = os.path.join(prefix.stdout.strip(), "lib")
        os.symlink(self.library, os.path.join(libdir, "libnavlink.so.0"))
        empty = self.folder("no-pc")
        found = self.loaded(self.probe(library_lookup_environment(PKG_CONFIG_LIBDIR=empty), python=python,
                                       source_tree=False))
        self.assertEqual(os.path.realpath(os.path.dirname(found[0])), os.path.realpath(libdir))
        self.assertTrue(found[1].startswith(environment), found[1])
        if self.have_pkg_config:
            elsewhere = self.linked_library("pkg-config")
            pc = write_navlink_pc(self.folder("pc"), elsewhere)
            found = self.loaded(self.probe(library_lookup_environment(**pc), python=python, source_tree=False))
            self.assertEqual(os.path.dirname(found[0]), elsewhere, "pkg-config before the installed places")


class TypingTest(unittest.TestCase):
    def test_the_public_api_is_annotated(self):
        """Every public function and method (with the special methods of public classes) annotates its
        parameters and its return, and the annotations name things that exist."""
        with open(nl.__file__) as f:
            tree = ast.parse(f.read())
        functions = (ast.FunctionDef, ast.AsyncFunctionDef)
        public = [(None, node) for node in tree.body if isinstance(node, functions) and not node.name.startswith("_")]
        public += [(cls.name, node) for cls in tree.body if isinstance(cls, ast.ClassDef) and not cls.name.startswith("_")
                   for node in cls.body if isinstance(node, functions)
                   and (not node.name.startswith("_") or node.name.endswith("__"))]
        unannotated = []
        checked = 0
        for owner, function in public:
            arguments = function.args.args + function.args.kwonlyargs
            missing = [a.arg for a in arguments if a.annotation is None and a.arg not in ("self", "cls")]
            if missing or function.returns is None:
                unannotated.append("%s.%s %s" % (owner, function.name, missing))
            target = getattr(nl, function.name) if owner is None else vars(getattr(nl, owner))[function.name]
            typing.get_type_hints(getattr(target, "fget", target), vars(nl))
            checked += 1
        self.assertEqual(unannotated, [])
        self.assertGreater(checked, 100)


class InstalledPackageTest(unittest.TestCase):
    """A package built (pip install) while PKG_CONFIG_PATH named the library finds that library once the
    variable is gone: the wheel records the folder pkg-config named then."""

    def test_the_wheel_remembers_the_library_it_was_built_against(self):
        import shutil
        import zipfile
        import _navlink_build
        if shutil.which("pkg-config") is None:
            self.skipTest("no pkg-config")
        library_dir = os.path.dirname(os.path.realpath(nl.library_path))
        with tempfile.TemporaryDirectory() as pc_dir, tempfile.TemporaryDirectory() as wheel_dir, \
                tempfile.TemporaryDirectory() as site:
            with open(os.path.join(pc_dir, "navlink.pc"), "w") as pc:
                pc.write("libdir=%s\nName: NavLink\nDescription: test\nVersion: %d.%d.%d\nLibs: -L${libdir} -lnavlink\n"
                         "Cflags:\n" % (library_dir, nl.VERSION_MAJOR, nl.VERSION_MINOR, nl.VERSION_PATCH))
            saved = os.environ.get("PKG_CONFIG_PATH")
            os.environ["PKG_CONFIG_PATH"] = pc_dir
            try:
                wheel = _navlink_build.build_wheel(wheel_dir)
            finally:
                if saved is None:
                    del os.environ["PKG_CONFIG_PATH"]
                else:
                    os.environ["PKG_CONFIG_PATH"] = saved
            with zipfile.ZipFile(os.path.join(wheel_dir, wheel)) as archive:
                self.assertIn("navlink/_built_against.py", archive.namelist())
                archive.extractall(site)
            env = {k: v for k, v in os.environ.items()
                   if k not in ("PKG_CONFIG_PATH", "NAVLINK_LIBRARY", "LD_LIBRARY_PATH", "PYTHONPATH")}
            env["PYTHONPATH"] = site
            run = subprocess.run([sys.executable, "-c", "import navlink; print(navlink.library_path)"], cwd=site, env=env,
                                 capture_output=True, text=True, timeout=60)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(os.path.dirname(os.path.realpath(run.stdout.strip())), library_dir)


if __name__ == "__main__":
    unittest.main()
