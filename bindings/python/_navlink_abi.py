"""The C ABI of libnavlink for ctypes: generated from navlink/version.h, navlink/navlink.h (with its parts), navlink/recast.h, navlink/plugin.h by bindings/generate/generate.py.

Do not edit: change the header and run the generator (docs/bindings.md, "Generated layers"). navlink.py
imports everything here and builds the idiomatic layer on top.
"""
# Generated file. Do not edit.
# flake8: noqa
import enum
from ctypes import (CFUNCTYPE, POINTER, c_char, c_char_p, c_double, c_float, c_int, c_int32, c_size_t,
                    c_uint8, c_uint32, c_uint64, c_void_p)
from typing import Any, Dict, List, Tuple

try:
    from ._navlink_structs import _Growable, _Id, _read_as_enums, _Struct
except ImportError:  # navlink.py run where it is (bindings/python on sys.path)
    from _navlink_structs import _Growable, _Id, _read_as_enums, _Struct  # type: ignore[no-redef]


class LogLevel(enum.IntEnum):
    """Log levels passed to the log callback. (nl_log_level)"""
    ERROR = 0
    WARNING = 1
    INFO = 2
    DEBUG = 3


class LinkKind(enum.IntEnum):
    """Link kinds. Plugin kinds are numbered from NL_LINK_FIRST_PLUGIN_KIND. (nl_link_kind)"""
    JUMP = 1
    DROP = 2
    MANUAL = 3


class PathOutcome(enum.IntEnum):
    """How a path request ended. (nl_path_outcome)"""
    PENDING = 0
    COMPLETE = 1
    PARTIAL = 2
    NO_PATH = 3
    START_OFF_NAVMESH = 4
    GOAL_OFF_NAVMESH = 5
    CANCELLED = 6
    FAILED = 7


class SegmentKind(enum.IntEnum):
    """How the agent moves from one path point to the next: walking, or the kind of the link taken (NL_LINK_JUMP, NL_LINK_DROP, NL_LINK_MANUAL or a plugin kind). (nl_segment_kind)"""
    WALK = 0
    JUMP = 1
    DROP = 2
    MANUAL = 3


class PathShortfallReason(enum.IntEnum):
    """Why a path falls short of its goal: nl_path_shortfall.reason. (nl_path_shortfall_reason)"""
    NONE = 0
    OUT_OF_NODES = 1
    BODY_TOO_WIDE = 2
    AREAS_EXCLUDED = 3
    LINK_BEYOND_BODY = 4
    NO_LINKS = 5
    NOT_CONNECTED = 6


class LinkLimit(enum.IntEnum):
    """What a link asks that the body lacks: nl_path_shortfall.limit. (nl_link_limit)"""
    NONE = 0
    JUMP_DISTANCE = 1
    JUMP_HEIGHT = 2
    DROP_HEIGHT = 3
    WIDTH = 4
    ABILITIES = 5


class AgentState(enum.IntEnum):
    """What an agent is doing. (nl_agent_state)"""
    IDLE = 0
    WALKING = 1
    JUMPING = 2
    FALLING = 3
    TRAVERSING = 4
    WAITING = 5
    ARRIVED = 6
    FAILED = 7


class AgentReason(enum.IntEnum):
    """Why an agent planned again or failed (nl_agent_info.reason, nl_agent_event.reason). (nl_agent_reason)"""
    NONE = 0
    DESTINATION_SET = 1
    LINK_GONE = 2
    WORLD_CHANGED = 3
    OFF_PATH = 4
    NO_PATH = 5
    NAVMESH_REMOVED = 6
    CAPABILITIES_CHANGED = 7
    CROWD = 8


class TrajectoryKind(enum.IntEnum):
    """How a link is being taken: the trajectory the generator checked, with its timing, for a host that animates the body. (nl_trajectory_kind)"""
    NONE = 0
    ARC = 1
    FALL = 2
    LINE = 3


class AgentEventKind(enum.IntEnum):
    """What happened to an agent in the last step. (nl_agent_event_kind)"""
    PATH_READY = 1
    LINK_STARTED = 2
    LINK_FINISHED = 3
    ARRIVED = 4
    FAILED = 5
    REPLANNED = 6
    WAITING = 7


# Every NL_* constant of the headers, without its NL_ prefix (the kinds' as their IntEnum members).
VERSION_MAJOR = 0
VERSION_MINOR = 2
VERSION_PATCH = 0
STATUS_FAILURE = 0x80000000
STATUS_SUCCESS = 0x40000000
STATUS_IN_PROGRESS = 0x20000000
STATUS_DETAIL_MASK = 0xFFFFFFF
STATUS_INVALID_ARGUMENT = 1
STATUS_INVALID_HANDLE = 2
STATUS_BUFFER_TOO_SMALL = 4
STATUS_OUT_OF_MEMORY = 8
STATUS_CANCELLED = 16
STATUS_PARTIAL_RESULT = 32
STATUS_NOT_FOUND = 64
STATUS_INTERNAL_ERROR = 128
STATUS_IO_ERROR = 0x100
STATUS_PARSE_ERROR = 0x200
STATUS_VERSION_MISMATCH = 0x400
COORDINATE_LIMIT = 1000000000.0
LOG_ERROR = LogLevel.ERROR
LOG_WARNING = LogLevel.WARNING
LOG_INFO = LogLevel.INFO
LOG_DEBUG = LogLevel.DEBUG
WORKERS_AUTO = -1
MAX_WORKERS = 0x400
MESH_MOVABLE = 1
MESH_CLOCKWISE = 2
MESH_OBSTACLE = 4
MESH_NOT_IN_NAVMESH = 8
MESH_MAX_AREA = 254
UP_AXIS_NOT_SAID = 0
UP_AXIS_Y = 1
UP_AXIS_Z = 2
MAX_POLYGON_VERTICES = 16
NO_POLYGON = 0xFFFFFFFF
BUILD_WARNING_CLOCKWISE = 1
BUILD_WARNING_UNITS = 2
BUILD_WARNING_Z_UP = 4
LINK_FIRST_PLUGIN_KIND = 0x100
LINK_JUMP = LinkKind.JUMP
LINK_DROP = LinkKind.DROP
LINK_MANUAL = LinkKind.MANUAL
LINKS_LOAD_ANY_BODY = 1
NAVMESH_LOAD_SAME_LEVEL = 1
AREA_EXCLUDED = 0.0
PATH_PENDING = PathOutcome.PENDING
PATH_COMPLETE = PathOutcome.COMPLETE
PATH_PARTIAL = PathOutcome.PARTIAL
PATH_NO_PATH = PathOutcome.NO_PATH
PATH_START_OFF_NAVMESH = PathOutcome.START_OFF_NAVMESH
PATH_GOAL_OFF_NAVMESH = PathOutcome.GOAL_OFF_NAVMESH
PATH_CANCELLED = PathOutcome.CANCELLED
PATH_FAILED = PathOutcome.FAILED
SEGMENT_WALK = SegmentKind.WALK
SEGMENT_JUMP = SegmentKind.JUMP
SEGMENT_DROP = SegmentKind.DROP
SEGMENT_MANUAL = SegmentKind.MANUAL
PATH_SHORTFALL_NONE = PathShortfallReason.NONE
PATH_SHORTFALL_OUT_OF_NODES = PathShortfallReason.OUT_OF_NODES
PATH_SHORTFALL_BODY_TOO_WIDE = PathShortfallReason.BODY_TOO_WIDE
PATH_SHORTFALL_AREAS_EXCLUDED = PathShortfallReason.AREAS_EXCLUDED
PATH_SHORTFALL_LINK_BEYOND_BODY = PathShortfallReason.LINK_BEYOND_BODY
PATH_SHORTFALL_NO_LINKS = PathShortfallReason.NO_LINKS
PATH_SHORTFALL_NOT_CONNECTED = PathShortfallReason.NOT_CONNECTED
LINK_LIMIT_NONE = LinkLimit.NONE
LINK_LIMIT_JUMP_DISTANCE = LinkLimit.JUMP_DISTANCE
LINK_LIMIT_JUMP_HEIGHT = LinkLimit.JUMP_HEIGHT
LINK_LIMIT_DROP_HEIGHT = LinkLimit.DROP_HEIGHT
LINK_LIMIT_WIDTH = LinkLimit.WIDTH
LINK_LIMIT_ABILITIES = LinkLimit.ABILITIES
PATH_WAIT_FOREVER = 0xFFFFFFFF
NO_ISLAND = 0xFFFFFFFF
AGENT_IDLE = AgentState.IDLE
AGENT_WALKING = AgentState.WALKING
AGENT_JUMPING = AgentState.JUMPING
AGENT_FALLING = AgentState.FALLING
AGENT_TRAVERSING = AgentState.TRAVERSING
AGENT_WAITING = AgentState.WAITING
AGENT_ARRIVED = AgentState.ARRIVED
AGENT_FAILED = AgentState.FAILED
AGENT_REASON_NONE = AgentReason.NONE
AGENT_REASON_DESTINATION_SET = AgentReason.DESTINATION_SET
AGENT_REASON_LINK_GONE = AgentReason.LINK_GONE
AGENT_REASON_WORLD_CHANGED = AgentReason.WORLD_CHANGED
AGENT_REASON_OFF_PATH = AgentReason.OFF_PATH
AGENT_REASON_NO_PATH = AgentReason.NO_PATH
AGENT_REASON_NAVMESH_REMOVED = AgentReason.NAVMESH_REMOVED
AGENT_REASON_CAPABILITIES_CHANGED = AgentReason.CAPABILITIES_CHANGED
AGENT_REASON_CROWD = AgentReason.CROWD
TRAJECTORY_NONE = TrajectoryKind.NONE
TRAJECTORY_ARC = TrajectoryKind.ARC
TRAJECTORY_FALL = TrajectoryKind.FALL
TRAJECTORY_LINE = TrajectoryKind.LINE
AGENT_EVENT_PATH_READY = AgentEventKind.PATH_READY
AGENT_EVENT_LINK_STARTED = AgentEventKind.LINK_STARTED
AGENT_EVENT_LINK_FINISHED = AgentEventKind.LINK_FINISHED
AGENT_EVENT_ARRIVED = AgentEventKind.ARRIVED
AGENT_EVENT_FAILED = AgentEventKind.FAILED
AGENT_EVENT_REPLANNED = AgentEventKind.REPLANNED
AGENT_EVENT_WAITING = AgentEventKind.WAITING
PLUGIN_NAVMESH_BUILDER = 1
PLUGIN_LINK_KIND = 2
RECAST_PARTITION_WATERSHED = 0
RECAST_PARTITION_MONOTONE = 1
RECAST_PARTITION_LAYERS = 2
PLUGIN_ABI_VERSION = 1
PLUGIN_ENTRY_SYMBOL = "nl_plugin_entry"
BUILD_AREA_OBSTACLE = 255


# Structs, as ctypes classes (fields under their C names; set below, in header order).


class Version(_Struct):
    """Semantic version of the library. (nl_version)"""


class MeshId(_Id):
    """A registered mesh. Zero-initialised is the null id. (nl_mesh_id)"""


class NavmeshId(_Id):
    """A navmesh in a world. Zero-initialised is the null id. (nl_navmesh_id)"""


class LinkId(_Id):
    """A link in a world. Zero-initialised is the null id. (nl_link_id)"""


class PathTicket(_Id):
    """A queued path request. Zero-initialised is the null ticket. (nl_path_ticket)"""


class AgentId(_Id):
    """An agent in a world. Zero-initialised is the null id. (nl_agent_id)"""


class PluginId(_Id):
    """A plugin loaded in a world. Zero-initialised is the null id. (nl_plugin_id)"""


class WorldDef(_Struct):
    """How to create a world. Get one from nl_default_world_def(). (nl_world_def)"""


class MeshDef(_Struct):
    """Describes a triangle mesh to register. Get one from nl_default_mesh_def(). (nl_mesh_def)"""


class MeshInfo(_Growable):
    """What a registered mesh holds. (nl_mesh_info)"""


class Ray(_Struct):
    """A ray from `origin` along `direction` (any nonzero length; normalised internally), up to `max_distance` metres (> 0; INFINITY allowed). (nl_ray)"""


class RayHit(_Growable):
    """The closest hit of a ray. An array element that may grow: set out_hits[0].size (nl_ray_hit_init). (nl_ray_hit)"""


class Segment(_Struct):
    """A straight segment between two points. (nl_segment)"""


class AgentType(_Struct):
    """The body a navmesh is made for. (nl_agent_type)"""


class NavmeshDef(_Struct):
    """A navmesh handed over by the host. Get one from nl_default_navmesh_def(). (nl_navmesh_def)"""


class NavmeshInfo(_Growable):
    """Sizes of a navmesh and what was repaired when it was added. (nl_navmesh_info)"""


class NavPolygon(_Growable):
    """One polygon: corners counter-clockwise seen from above, and the neighbour across each edge. May grow: set `size` (nl_nav_polygon_init). (nl_nav_polygon)"""


class BoundaryEdge(_Struct):
    """An edge of the navmesh's outline: owned by exactly one polygon. Jump and drop links start here. (nl_boundary_edge)"""


class NavPoint(_Struct):
    """Where a point lies on a navmesh. (nl_nav_point)"""


class NavmeshBuildDef(_Struct):
    """How to build a navmesh. Get one from nl_default_navmesh_build_def(). (nl_navmesh_build_def)"""


class LinkRequirements(_Struct):
    """What taking a link asks of an agent, going from its start to its end. Going the other way over a bidirectional link swaps rise and drop. (nl_link_requirements)"""


class Link(_Growable):
    """A link as the world holds it. An array element that may grow: set `size` of the first element of an output array (nl_link_init). (nl_link)"""


class LinkDef(_Struct):
    """A link to add, or the new state of one to update. Get one from nl_default_link_def(). (nl_link_def)"""


class LinkSettings(_Struct):
    """How links are generated (docs/link-generation.md explains each). Get one from nl_default_link_settings(); defaults work with Recast's default agent on the shared levels. (nl_link_settings)"""


class LinkGenerationReport(_Growable):
    """What a generation did: answers "why is there no link here?". (nl_link_generation_report)"""


class NavmeshLoadDef(_Struct):
    """How to load a navmesh file. Get one from nl_default_navmesh_load_def(). (nl_navmesh_load_def)"""


class NavmeshFileInfo(_Struct):
    """What a navmesh file holds and was made for (nl_navmesh_file_describe). (nl_navmesh_file_info)"""


class AgentCapabilities(_Struct):
    """What an agent's body can do. A link is usable only if the agent meets all of its requirements: gap <= max_jump_distance, rise <= max_jump_height, drop <= max_drop_height, clearance_width (when measured) >= 2 * radius, and every ability bit it asks for. Going the other way over a bidirectional link swaps rise and drop. A drop taken downward is a step off the edge, not a jump: its gap is not held against max_jump_distance. (nl_agent_capabilities)"""


class PathRequestDef(_Struct):
    """One path request. Get one from nl_default_path_request_def(). (nl_path_request_def)"""


class PathPoint(_Growable):
    """One point of a path. An array element that may grow: set `size` of the first element of an output array (nl_path_point_init). (nl_path_point)"""


class PathResultInfo(_Growable):
    """What a finished request found. (nl_path_result)"""


class PathShortfallInfo(_Growable):
    """Why a request's path falls short of its goal (nl_path_explain). (nl_path_shortfall)"""


class PathBudget(_Struct):
    """How much nl_path_process may do in one call. Get one from nl_default_path_budget() (no limits). A request is never split: the budget is checked between requests, so a call that finds the queue non-empty plans at least one, and the request that crosses a limit finishes. (nl_path_budget)"""


class PathFinished(_Growable):
    """A request that finished, as nl_path_take_finished reports it. An array element that may grow: set `size` of the first element (nl_path_finished_init). (nl_path_finished)"""


class PathQueueStats(_Growable):
    """Counters of a world's path queue. (nl_path_queue_stats)"""


class QueryFilterDef(_Struct):
    """The body a query is for, as a path request gives it: its capabilities (the links it can take, the room a wider body needs) and its area costs (an area of cost NL_AREA_EXCLUDED is kept out of; other costs do not matter to these queries). Get one from nl_default_query_filter(). (nl_query_filter)"""


class NavmeshRay(_Struct):
    """One straight walk for nl_navmesh_raycast. (nl_navmesh_ray)"""


class NavmeshRaycastHit(_Growable):
    """How far a straight walk along a navmesh went (nl_navmesh_raycast). An array element that may grow: set `size` of the first element of the output array (nl_navmesh_raycast_hit_init). (nl_navmesh_raycast_hit)"""


class RandomPointsDef(_Struct):
    """Which random points nl_navmesh_random_points draws. Get one from nl_default_random_points_def(). (nl_random_points_def)"""


class AgentDef(_Struct):
    """How to add an agent. Get one from nl_default_agent_def(). (nl_agent_def)"""


class AgentInfo(_Growable):
    """An agent's state. An array element that may grow: set `size` of the first (nl_agent_info_init). (nl_agent_info)"""


class AgentTrajectory(_Growable):
    """(nl_agent_trajectory)"""


class AgentEvent(_Growable):
    """An array element that may grow: set `size` of the first (nl_agent_event_init). (nl_agent_event)"""


class PluginDescription(_Growable):
    """What a loaded plugin is. Strings are owned by the world and live until it is destroyed. (nl_plugin_description)"""


class RecastSettings(_Struct):
    """(nl_recast_settings)"""


class PluginHost(_Struct):
    """Functions the host offers a plugin. `context` is passed back as the first argument of each. Valid for as long as the plugin is loaded. (nl_plugin_host)"""


class NavmeshBuilder(_Struct):
    """What a navmesh-builder plugin provides. (nl_navmesh_builder)"""


class LinkKindProvider(_Struct):
    """What a link-kind plugin provides: links of a kind of its own, generated with the built-in ones by nl_navmesh_generate_links (and again in full by nl_navmesh_update_links_in_box). (nl_link_kind_provider)"""


class PluginInfo(_Struct):
    """What a plugin tells the host about itself. The host zero-fills it and sets `size` first. (nl_plugin_info)"""


Version._fields_ = [("major", c_int32), ("minor", c_int32), ("patch", c_int32)]
LogFn = CFUNCTYPE(None, c_void_p, c_uint32, c_uint32, c_char_p)
TaskFn = CFUNCTYPE(None, c_void_p, c_uint32, c_uint32, c_uint32)
TaskEnqueueFn = CFUNCTYPE(c_void_p, c_void_p, TaskFn, c_void_p, c_uint32, c_uint32)
TaskFinishFn = CFUNCTYPE(None, c_void_p, c_void_p)
WorldDef._fields_ = [("size", c_uint32), ("worker_count", c_int32), ("log_fn", LogFn), ("log_user", c_void_p),
                      ("log_level", c_uint32), ("reserved", c_uint32), ("path_worker_count", c_int32),
                      ("task_enqueue_fn", TaskEnqueueFn), ("task_finish_fn", TaskFinishFn), ("task_user", c_void_p),
                      ("agent_paths_per_step", c_uint32), ("reserved2", c_uint32)]
MeshDef._fields_ = [("size", c_uint32), ("vertices", POINTER(c_float)), ("vertex_count", c_uint32),
                     ("vertex_stride", c_uint32), ("indices", POINTER(c_uint32)), ("triangle_count", c_uint32),
                     ("flags", c_uint32), ("transform", POINTER(c_float)), ("user_data", c_uint64),
                     ("area", c_uint32), ("reserved", c_uint32), ("metres_per_unit", c_float), ("up_axis", c_uint32)]
MeshInfo._fields_ = [("size", c_uint32), ("vertex_count", c_uint32), ("triangle_count", c_uint32),
                      ("degenerate_triangle_count", c_uint32), ("flags", c_uint32), ("transform", c_float * 16),
                      ("bounds_min", c_float * 3), ("bounds_max", c_float * 3), ("user_data", c_uint64),
                      ("area", c_uint32), ("reserved", c_uint32), ("metres_per_unit", c_float),
                      ("up_axis", c_uint32)]
Ray._fields_ = [("origin", c_float * 3), ("direction", c_float * 3), ("max_distance", c_float)]
RayHit._fields_ = [("size", c_uint32), ("distance", c_float), ("point", c_float * 3), ("normal", c_float * 3),
                    ("mesh", MeshId), ("triangle", c_uint32), ("hit", c_uint8), ("reserved", c_uint8 * 3)]
Segment._fields_ = [("from", c_float * 3), ("to", c_float * 3)]
AgentType._fields_ = [("radius", c_float), ("height", c_float), ("max_climb", c_float), ("max_slope", c_float)]
NavmeshDef._fields_ = [("size", c_uint32), ("vertices", POINTER(c_float)), ("vertex_count", c_uint32),
                        ("vertex_stride", c_uint32), ("indices", POINTER(c_uint32)),
                        ("polygon_vertex_counts", POINTER(c_uint8)), ("polygon_count", c_uint32),
                        ("areas", POINTER(c_uint8)), ("weld_tolerance", c_float), ("agent", AgentType),
                        ("detail_vertices", POINTER(c_float)), ("detail_vertex_count", c_uint32),
                        ("detail_triangles", POINTER(c_uint32)), ("detail_triangle_count", c_uint32),
                        ("detail_triangle_starts", POINTER(c_uint32)), ("surface", MeshId)]
NavmeshInfo._fields_ = [("size", c_uint32), ("vertex_count", c_uint32), ("polygon_count", c_uint32),
                         ("portal_count", c_uint32), ("boundary_edge_count", c_uint32),
                         ("welded_vertex_count", c_uint32), ("flipped_polygon_count", c_uint32),
                         ("dropped_polygon_count", c_uint32), ("non_manifold_edge_count", c_uint32),
                         ("agent", AgentType), ("bounds_min", c_float * 3), ("bounds_max", c_float * 3),
                         ("surface", MeshId), ("turned_over_mesh_count", c_uint32), ("build_warnings", c_uint32)]
NavPolygon._fields_ = [("size", c_uint32), ("vertex_count", c_uint32), ("vertices", c_uint32 * 16),
                        ("neighbours", c_uint32 * 16), ("area", c_uint32), ("normal", c_float * 3),
                        ("centre", c_float * 3)]
BoundaryEdge._fields_ = [("start", c_float * 3), ("end", c_float * 3), ("outward", c_float * 3),
                          ("normal", c_float * 3), ("polygon", c_uint32), ("edge", c_uint32)]
NavPoint._fields_ = [("point", c_float * 3), ("distance", c_float), ("polygon", c_uint32), ("found", c_uint8),
                      ("beyond_box", c_uint8), ("reserved", c_uint8 * 2)]
ProgressFn = CFUNCTYPE(c_int32, c_void_p, c_float, c_char_p)
NavmeshBuildDef._fields_ = [("size", c_uint32), ("builder", c_char_p), ("agent", AgentType), ("settings", c_void_p),
                             ("settings_json", c_char_p), ("settings_json_length", c_size_t), ("surface", MeshId),
                             ("progress", ProgressFn), ("progress_user", c_void_p)]
LinkRequirements._fields_ = [("gap", c_float), ("rise", c_float), ("drop", c_float), ("clearance_width", c_float),
                              ("abilities", c_uint64), ("length", c_float), ("reserved", c_uint32)]
Link._fields_ = [("size", c_uint32), ("kind", c_uint32), ("id", LinkId), ("navmesh", NavmeshId),
                  ("start", c_float * 3), ("end", c_float * 3), ("apex", c_float * 3), ("bidirectional", c_uint8),
                  ("generated", c_uint8), ("enabled", c_uint8), ("reserved", c_uint8), ("cost_modifier", c_float),
                  ("start_polygon", c_uint32), ("end_polygon", c_uint32), ("reserved2", c_uint32),
                  ("user_data", c_uint64), ("requirements", LinkRequirements), ("landing_navmesh", NavmeshId),
                  ("tolerance", c_float), ("holds", c_uint8), ("reserved3", c_uint8 * 3)]
LinkDef._fields_ = [("size", c_uint32), ("kind", c_uint32), ("start", c_float * 3), ("end", c_float * 3),
                     ("bidirectional", c_uint8), ("enabled", c_uint8), ("requirements_as_given", c_uint8),
                     ("reserved", c_uint8), ("cost_modifier", c_float), ("user_data", c_uint64),
                     ("requirements", LinkRequirements), ("landing_navmesh", NavmeshId), ("tolerance", c_float),
                     ("reserved2", c_uint32)]
LinkSettings._fields_ = [("size", c_uint32), ("min_edge_length", c_float), ("min_group_size", c_uint32),
                          ("max_group_size", c_uint32), ("sample_spacing", c_float), ("falloff_distance", c_float),
                          ("max_jump_gap", c_float), ("min_link_distance", c_float),
                          ("short_link_distance", c_float), ("max_jump_up", c_float), ("jump_arc_height", c_float),
                          ("strict_forward_angle", c_float), ("permissive_forward_angle", c_float),
                          ("strict_incline_angle", c_float), ("permissive_incline_angle", c_float),
                          ("max_drop_distance", c_float), ("drop_angles", c_float * 16),
                          ("drop_angle_count", c_uint32), ("drop_steepness", c_float), ("merge_distance", c_float),
                          ("clearance_margin", c_float), ("arc_segments", c_uint32),
                          ("plugin_settings_json", c_char_p), ("plugin_settings_json_length", c_size_t),
                          ("walk_factor", c_float), ("walk_distance", c_float)]
LinkGenerationReport._fields_ = [("size", c_uint32), ("edges", c_uint32), ("groups", c_uint32),
                                  ("samples", c_uint32), ("takeoff_points", c_uint32), ("jump_candidates", c_uint32),
                                  ("drop_candidates", c_uint32), ("jump_links", c_uint32), ("drop_links", c_uint32),
                                  ("plugin_links", c_uint32), ("rejected_wall", c_uint32),
                                  ("rejected_not_ledge", c_uint32), ("rejected_distance", c_uint32),
                                  ("rejected_rise", c_uint32), ("rejected_angle", c_uint32),
                                  ("rejected_no_landing", c_uint32), ("rejected_clearance", c_uint32),
                                  ("rejected_duplicate", c_uint32), ("rays_cast", c_uint64),
                                  ("milliseconds_edges", c_double), ("milliseconds_takeoff", c_double),
                                  ("milliseconds_jumps", c_double), ("milliseconds_drops", c_double),
                                  ("milliseconds_merge", c_double), ("milliseconds_total", c_double),
                                  ("box_queries", c_uint64), ("body_tests", c_uint64),
                                  ("rejected_walkable", c_uint32), ("rejected_too_shallow", c_uint32),
                                  ("rejected_too_deep", c_uint32), ("reserved", c_uint32)]
NavmeshLoadDef._fields_ = [("size", c_uint32), ("surface", MeshId), ("flags", c_uint32)]
NavmeshFileInfo._fields_ = [("size", c_uint32), ("version", c_uint32), ("file_size", c_uint64),
                             ("agent", AgentType), ("vertex_count", c_uint32), ("polygon_count", c_uint32),
                             ("detail_triangle_count", c_uint32), ("link_count", c_uint32),
                             ("generated_link_count", c_uint32), ("rides_surface", c_uint32), ("quantum", c_float),
                             ("reserved", c_uint32), ("level_hash", c_uint64)]
AgentCapabilities._fields_ = [("max_jump_distance", c_float), ("max_jump_height", c_float),
                               ("max_drop_height", c_float), ("radius", c_float), ("abilities", c_uint64)]
PathCallback = CFUNCTYPE(None, c_void_p, PathTicket, c_uint32)
PathRequestDef._fields_ = [("size", c_uint32), ("navmesh", NavmeshId), ("start", c_float * 3),
                            ("goal", c_float * 3), ("search_half_extents", c_float * 3),
                            ("agent", AgentCapabilities), ("area_costs", POINTER(c_float)),
                            ("area_cost_count", c_uint32), ("link_cost", c_float), ("max_nodes", c_uint32),
                            ("accept_partial", c_uint8), ("reserved", c_uint8 * 3), ("callback", PathCallback),
                            ("user", c_void_p)]
PathPoint._fields_ = [("size", c_uint32), ("position", c_float * 3), ("polygon", c_uint32), ("segment", c_uint32),
                       ("link", LinkId), ("apex", c_float * 3), ("reversed", c_uint8), ("reserved", c_uint8 * 3),
                       ("surface_position", c_float * 3)]
PathResultInfo._fields_ = [("size", c_uint32), ("outcome", c_uint32), ("status", c_uint32),
                            ("point_count", c_uint32), ("links_used", c_uint32), ("nodes_visited", c_uint32),
                            ("out_of_nodes", c_uint8), ("reserved", c_uint8 * 3), ("length", c_float),
                            ("cost", c_float), ("start", c_float * 3), ("goal", c_float * 3)]
PathShortfallInfo._fields_ = [("size", c_uint32), ("reason", c_uint32), ("limit", c_uint32), ("needed", c_float),
                               ("has", c_float), ("reversed", c_uint32), ("missing_abilities", c_uint64),
                               ("link", LinkId), ("link_start", c_float * 3), ("text", c_char * 256)]
PathBudget._fields_ = [("size", c_uint32), ("max_requests", c_uint32), ("max_milliseconds", c_double),
                        ("max_search_nodes", c_uint64)]
PathFinished._fields_ = [("size", c_uint32), ("outcome", c_uint32), ("ticket", PathTicket), ("user", c_void_p)]
PathQueueStats._fields_ = [("size", c_uint32), ("workers", c_uint32), ("queued", c_uint32), ("running", c_uint32),
                            ("unreleased", c_uint32), ("reserved", c_uint32), ("submitted", c_uint64),
                            ("finished", c_uint64)]
QueryFilterDef._fields_ = [("size", c_uint32), ("agent", AgentCapabilities), ("area_costs", POINTER(c_float)),
                            ("area_cost_count", c_uint32), ("reserved", c_uint32)]
NavmeshRay._fields_ = [("start", c_float * 3), ("start_polygon", c_uint32), ("end", c_float * 3)]
NavmeshRaycastHit._fields_ = [("size", c_uint32), ("hit", c_uint8), ("reserved", c_uint8 * 3), ("t", c_float),
                               ("point", c_float * 3), ("wall_normal", c_float * 3), ("end_polygon", c_uint32),
                               ("polygon_count", c_uint32)]
RandomPointsDef._fields_ = [("size", c_uint32), ("filter", POINTER(QueryFilterDef)), ("centre", c_float * 3),
                             ("radius", c_float), ("reachable_from", c_uint32), ("reserved", c_uint32),
                             ("seed", c_uint64)]
AgentDef._fields_ = [("size", c_uint32), ("navmesh", NavmeshId), ("height", c_float),
                      ("capabilities", AgentCapabilities), ("max_speed", c_float), ("max_acceleration", c_float),
                      ("gravity", c_float), ("takeoff_speed", c_float), ("position", c_float * 3),
                      ("avoidance", c_uint8), ("reserved", c_uint8 * 3), ("user_data", c_uint64),
                      ("give_up_seconds", c_float), ("reserved2", c_uint32)]
AgentInfo._fields_ = [("size", c_uint32), ("state", c_uint32), ("id", AgentId), ("position", c_float * 3),
                       ("velocity", c_float * 3), ("polygon", c_uint32), ("reason", c_uint32), ("link", LinkId),
                       ("link_progress", c_float), ("destination", c_float * 3), ("has_destination", c_uint8),
                       ("reserved", c_uint8 * 3), ("corners_ahead", c_uint32), ("user_data", c_uint64),
                       ("navmesh", NavmeshId), ("surface", MeshId), ("surface_position", c_float * 3),
                       ("reserved2", c_uint32)]
AgentTrajectory._fields_ = [("size", c_uint32), ("kind", c_uint32), ("link", LinkId), ("from", c_float * 3),
                             ("to", c_float * 3), ("apex", c_float * 3), ("points", (c_float * 3) * 4),
                             ("duration", c_float), ("elapsed", c_float)]
AgentEvent._fields_ = [("size", c_uint32), ("kind", c_uint32), ("agent", AgentId), ("link", LinkId),
                        ("reason", c_uint32), ("reserved", c_uint32), ("user_data", c_uint64)]
PluginDescription._fields_ = [("size", c_uint32), ("abi_version", c_uint32), ("kinds", c_uint32),
                               ("builtin", c_uint32), ("name", c_char_p), ("version", c_char_p),
                               ("description", c_char_p)]
RecastSettings._fields_ = [("size", c_uint32), ("cell_size", c_float), ("cell_height", c_float),
                            ("region_min_size", c_float), ("region_merge_size", c_float),
                            ("edge_max_length", c_float), ("edge_max_error", c_float),
                            ("vertices_per_polygon", c_uint32), ("detail_sample_distance", c_float),
                            ("detail_sample_max_error", c_float), ("partition", c_uint32),
                            ("filter_low_hanging_obstacles", c_uint8), ("filter_ledge_spans", c_uint8),
                            ("filter_walkable_low_height_spans", c_uint8), ("reserved", c_uint8)]
HostLogFn = CFUNCTYPE(None, c_void_p, c_uint32, c_char_p)
HostSetErrorFn = CFUNCTYPE(None, c_void_p, c_char_p)
HostGetLevelTrianglesFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(c_float), c_uint32, POINTER(c_uint32), POINTER(c_uint32), c_uint32, POINTER(c_uint32))
HostNavmeshGetBoundaryEdgesFn = CFUNCTYPE(c_uint32, c_void_p, NavmeshId, POINTER(BoundaryEdge), c_uint32, POINTER(c_uint32))
HostNavmeshGetInfoFn = CFUNCTYPE(c_uint32, c_void_p, NavmeshId, POINTER(NavmeshInfo))
HostNavmeshFindNearestFn = CFUNCTYPE(c_uint32, c_void_p, NavmeshId, POINTER(c_float), c_uint32, POINTER(c_float), POINTER(NavPoint))
HostCastRaysFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(Ray), c_uint32, POINTER(RayHit))
HostSegmentsBlockedFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(Segment), c_uint32, POINTER(c_uint8))
HostRecordBuildSettingsFn = CFUNCTYPE(c_uint32, c_void_p, c_char_p, c_size_t)
HostGetBuildTrianglesFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(c_float), c_uint32, POINTER(c_uint32), POINTER(c_uint32), POINTER(c_uint8), c_uint32, POINTER(c_uint32))
HostReportBuildProgressFn = CFUNCTYPE(c_uint32, c_void_p, c_float, c_char_p)
PluginHost._fields_ = [("size", c_uint32), ("abi_version", c_uint32), ("context", c_void_p), ("log", HostLogFn),
                        ("set_error", HostSetErrorFn), ("get_level_triangles", HostGetLevelTrianglesFn),
                        ("navmesh_get_boundary_edges", HostNavmeshGetBoundaryEdgesFn),
                        ("navmesh_get_info", HostNavmeshGetInfoFn),
                        ("navmesh_find_nearest", HostNavmeshFindNearestFn), ("cast_rays", HostCastRaysFn),
                        ("segments_blocked", HostSegmentsBlockedFn),
                        ("record_build_settings", HostRecordBuildSettingsFn),
                        ("get_build_triangles", HostGetBuildTrianglesFn),
                        ("report_build_progress", HostReportBuildProgressFn)]
NavmeshSinkFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(NavmeshDef))
NavmeshBuildFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(PluginHost), POINTER(NavmeshBuildDef), NavmeshSinkFn, c_void_p)
NavmeshBuilder._fields_ = [("build", NavmeshBuildFn)]
LinkSinkFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(LinkDef))
LinkGenerateFn = CFUNCTYPE(c_uint32, c_void_p, POINTER(PluginHost), NavmeshId, c_char_p, c_size_t, LinkSinkFn, c_void_p)
LinkKindProvider._fields_ = [("kind", c_uint32), ("kind_name", c_char_p), ("generate", LinkGenerateFn)]
PluginDestroyFn = CFUNCTYPE(None, c_void_p)
PluginInfo._fields_ = [("size", c_uint32), ("abi_version", c_uint32), ("name", c_char_p), ("version", c_char_p),
                        ("description", c_char_p), ("kinds", c_uint32), ("state", c_void_p),
                        ("destroy", PluginDestroyFn), ("navmesh_builder", NavmeshBuilder),
                        ("link_kind", LinkKindProvider)]
PluginEntryFn = CFUNCTYPE(c_uint32, c_uint32, POINTER(PluginHost), POINTER(PluginInfo))

# Fields of the header's kinds read as their IntEnums (AgentInfo.state is an AgentState...).
_read_as_enums(WorldDef, log_level=LogLevel)
_read_as_enums(Link, kind=LinkKind)
_read_as_enums(LinkDef, kind=LinkKind)
_read_as_enums(PathPoint, segment=SegmentKind)
_read_as_enums(PathResultInfo, outcome=PathOutcome)
_read_as_enums(PathShortfallInfo, reason=PathShortfallReason, limit=LinkLimit)
_read_as_enums(PathFinished, outcome=PathOutcome)
_read_as_enums(AgentInfo, state=AgentState, reason=AgentReason)
_read_as_enums(AgentTrajectory, kind=TrajectoryKind)
_read_as_enums(AgentEvent, kind=AgentEventKind, reason=AgentReason)
_read_as_enums(LinkKindProvider, kind=LinkKind)

# Every C struct by its C name.
C_STRUCTS = {
    "nl_version": Version, "nl_mesh_id": MeshId, "nl_navmesh_id": NavmeshId, "nl_link_id": LinkId,
    "nl_path_ticket": PathTicket, "nl_agent_id": AgentId, "nl_plugin_id": PluginId, "nl_world_def": WorldDef,
    "nl_mesh_def": MeshDef, "nl_mesh_info": MeshInfo, "nl_ray": Ray, "nl_ray_hit": RayHit, "nl_segment": Segment,
    "nl_agent_type": AgentType, "nl_navmesh_def": NavmeshDef, "nl_navmesh_info": NavmeshInfo,
    "nl_nav_polygon": NavPolygon, "nl_boundary_edge": BoundaryEdge, "nl_nav_point": NavPoint,
    "nl_navmesh_build_def": NavmeshBuildDef, "nl_link_requirements": LinkRequirements, "nl_link": Link,
    "nl_link_def": LinkDef, "nl_link_settings": LinkSettings, "nl_link_generation_report": LinkGenerationReport,
    "nl_navmesh_load_def": NavmeshLoadDef, "nl_navmesh_file_info": NavmeshFileInfo,
    "nl_agent_capabilities": AgentCapabilities, "nl_path_request_def": PathRequestDef,
    "nl_path_point": PathPoint, "nl_path_result": PathResultInfo, "nl_path_shortfall": PathShortfallInfo,
    "nl_path_budget": PathBudget, "nl_path_finished": PathFinished, "nl_path_queue_stats": PathQueueStats,
    "nl_query_filter": QueryFilterDef, "nl_navmesh_ray": NavmeshRay, "nl_navmesh_raycast_hit": NavmeshRaycastHit,
    "nl_random_points_def": RandomPointsDef, "nl_agent_def": AgentDef, "nl_agent_info": AgentInfo,
    "nl_agent_trajectory": AgentTrajectory, "nl_agent_event": AgentEvent,
    "nl_plugin_description": PluginDescription, "nl_recast_settings": RecastSettings,
    "nl_plugin_host": PluginHost, "nl_navmesh_builder": NavmeshBuilder,
    "nl_link_kind_provider": LinkKindProvider, "nl_plugin_info": PluginInfo,
}


# The header's inline initialisers (NL_DEFINE_OUTPUT_INIT): not exported by the library, so defined
# here under their C names. Each is a new struct of the class, whose constructor sets `size`.


def nl_mesh_info_init() -> MeshInfo:
    return MeshInfo()


def nl_ray_hit_init() -> RayHit:
    return RayHit()


def nl_navmesh_info_init() -> NavmeshInfo:
    return NavmeshInfo()


def nl_nav_polygon_init() -> NavPolygon:
    return NavPolygon()


def nl_link_init() -> Link:
    return Link()


def nl_link_generation_report_init() -> LinkGenerationReport:
    return LinkGenerationReport()


def nl_path_point_init() -> PathPoint:
    return PathPoint()


def nl_path_result_init() -> PathResultInfo:
    return PathResultInfo()


def nl_path_shortfall_init() -> PathShortfallInfo:
    return PathShortfallInfo()


def nl_path_finished_init() -> PathFinished:
    return PathFinished()


def nl_path_queue_stats_init() -> PathQueueStats:
    return PathQueueStats()


def nl_navmesh_raycast_hit_init() -> NavmeshRaycastHit:
    return NavmeshRaycastHit()


def nl_agent_info_init() -> AgentInfo:
    return AgentInfo()


def nl_agent_trajectory_init() -> AgentTrajectory:
    return AgentTrajectory()


def nl_agent_event_init() -> AgentEvent:
    return AgentEvent()


def nl_plugin_description_init() -> PluginDescription:
    return PluginDescription()


# Every exported function: name -> (return type, [parameter types]).
PROTOTYPES: Dict[str, Tuple[Any, List[Any]]] = {
    "nl_get_version": (Version, []),
    "nl_status_string": (c_char_p, [c_uint32]),
    "nl_get_last_status": (c_uint32, []),
    "nl_get_last_error_message": (c_char_p, []),
    "nl_default_world_def": (WorldDef, []),
    "nl_world_create": (c_uint32, [POINTER(WorldDef), POINTER(c_void_p)]),
    "nl_world_destroy": (None, [c_void_p]),
    "nl_world_get_worker_count": (c_int32, [c_void_p]),
    "nl_default_mesh_def": (MeshDef, []),
    "nl_mesh_add": (c_uint32, [c_void_p, POINTER(MeshDef), POINTER(MeshId)]),
    "nl_mesh_add_obj_file": (c_uint32, [c_void_p, c_char_p, POINTER(MeshDef), POINTER(MeshId)]),
    "nl_mesh_add_obj_memory": (c_uint32, [c_void_p, c_char_p, c_size_t, POINTER(MeshDef), POINTER(MeshId)]),
    "nl_mesh_remove": (c_uint32, [c_void_p, MeshId]),
    "nl_mesh_set_transform": (c_uint32, [c_void_p, MeshId, POINTER(c_float)]),
    "nl_mesh_is_valid": (c_int32, [c_void_p, MeshId]),
    "nl_mesh_get_info": (c_uint32, [c_void_p, MeshId, POINTER(MeshInfo)]),
    "nl_world_get_meshes": (c_uint32, [c_void_p, POINTER(MeshId), c_uint32, POINTER(c_uint32)]),
    "nl_world_cast_rays": (c_uint32, [c_void_p, POINTER(Ray), c_uint32, POINTER(RayHit)]),
    "nl_world_segments_blocked": (c_uint32, [c_void_p, POINTER(Segment), c_uint32, POINTER(c_uint8)]),
    "nl_default_agent_type": (AgentType, []),
    "nl_default_navmesh_def": (NavmeshDef, []),
    "nl_navmesh_add": (c_uint32, [c_void_p, POINTER(NavmeshDef), POINTER(NavmeshId)]),
    "nl_navmesh_remove": (c_uint32, [c_void_p, NavmeshId]),
    "nl_navmesh_is_valid": (c_int32, [c_void_p, NavmeshId]),
    "nl_navmesh_get_info": (c_uint32, [c_void_p, NavmeshId, POINTER(NavmeshInfo)]),
    "nl_navmesh_get_vertices": (c_uint32, [c_void_p, NavmeshId, POINTER(c_float), c_uint32, POINTER(c_uint32)]),
    "nl_navmesh_get_polygon": (c_uint32, [c_void_p, NavmeshId, c_uint32, POINTER(NavPolygon)]),
    "nl_navmesh_get_boundary_edges": (c_uint32, [c_void_p, NavmeshId, POINTER(BoundaryEdge), c_uint32, POINTER(c_uint32)]),
    "nl_navmesh_find_nearest": (c_uint32, [c_void_p, NavmeshId, POINTER(c_float), c_uint32, POINTER(c_float),
                                   POINTER(NavPoint)]),
    "nl_world_get_navmeshes": (c_uint32, [c_void_p, POINTER(NavmeshId), c_uint32, POINTER(c_uint32)]),
    "nl_default_navmesh_build_def": (NavmeshBuildDef, []),
    "nl_navmesh_build": (c_uint32, [c_void_p, POINTER(NavmeshBuildDef), POINTER(NavmeshId)]),
    "nl_default_link_def": (LinkDef, []),
    "nl_link_add": (c_uint32, [c_void_p, NavmeshId, POINTER(LinkDef), POINTER(LinkId)]),
    "nl_link_update": (c_uint32, [c_void_p, LinkId, POINTER(LinkDef)]),
    "nl_link_remove": (c_uint32, [c_void_p, LinkId]),
    "nl_link_is_valid": (c_int32, [c_void_p, LinkId]),
    "nl_link_get": (c_uint32, [c_void_p, LinkId, POINTER(Link)]),
    "nl_navmesh_get_links": (c_uint32, [c_void_p, NavmeshId, POINTER(Link), c_uint32, POINTER(c_uint32)]),
    "nl_navmesh_remove_generated_links": (c_uint32, [c_void_p, NavmeshId, POINTER(c_uint32)]),
    "nl_default_link_settings": (LinkSettings, []),
    "nl_link_settings_from_json": (c_uint32, [c_char_p, c_size_t, POINTER(LinkSettings)]),
    "nl_navmesh_generate_links": (c_uint32, [c_void_p, NavmeshId, POINTER(LinkSettings), ProgressFn, c_void_p,
                                     POINTER(LinkGenerationReport)]),
    "nl_navmesh_generate_cross_links": (c_uint32, [c_void_p, NavmeshId, NavmeshId, c_float, POINTER(LinkSettings),
                                           ProgressFn, c_void_p, POINTER(LinkGenerationReport)]),
    "nl_navmesh_update_links_in_box": (c_uint32, [c_void_p, NavmeshId, POINTER(c_float), POINTER(c_float), ProgressFn,
                                          c_void_p, POINTER(LinkGenerationReport)]),
    "nl_navmesh_save_links_json": (c_uint32, [c_void_p, NavmeshId, c_char_p, c_size_t, POINTER(c_size_t)]),
    "nl_navmesh_load_links_json": (c_uint32, [c_void_p, NavmeshId, c_char_p, c_size_t, c_uint32, POINTER(c_uint32)]),
    "nl_navmesh_save": (c_uint32, [c_void_p, NavmeshId, c_void_p, c_size_t, POINTER(c_size_t)]),
    "nl_navmesh_save_file": (c_uint32, [c_void_p, NavmeshId, c_char_p]),
    "nl_default_navmesh_load_def": (NavmeshLoadDef, []),
    "nl_navmesh_load": (c_uint32, [c_void_p, c_void_p, c_size_t, POINTER(NavmeshLoadDef), POINTER(NavmeshId)]),
    "nl_navmesh_load_file": (c_uint32, [c_void_p, c_char_p, POINTER(NavmeshLoadDef), POINTER(NavmeshId)]),
    "nl_navmesh_file_describe": (c_uint32, [c_void_p, c_size_t, POINTER(NavmeshFileInfo), c_char_p, c_size_t,
                                    POINTER(c_size_t)]),
    "nl_default_agent_capabilities": (AgentCapabilities, []),
    "nl_default_path_request_def": (PathRequestDef, []),
    "nl_path_find": (c_uint32, [c_void_p, POINTER(PathRequestDef), POINTER(PathResultInfo), POINTER(PathPoint), c_uint32,
                        POINTER(c_uint32)]),
    "nl_path_explain": (c_uint32, [c_void_p, POINTER(PathRequestDef), POINTER(PathShortfallInfo)]),
    "nl_path_request": (c_uint32, [c_void_p, POINTER(PathRequestDef), POINTER(PathTicket)]),
    "nl_path_poll": (c_uint32, [c_void_p, PathTicket, POINTER(c_uint32)]),
    "nl_path_wait": (c_uint32, [c_void_p, PathTicket, c_uint32, POINTER(c_uint32)]),
    "nl_path_get_result": (c_uint32, [c_void_p, PathTicket, POINTER(PathResultInfo), POINTER(PathPoint), c_uint32,
                              POINTER(c_uint32)]),
    "nl_path_cancel": (c_uint32, [c_void_p, PathTicket]),
    "nl_path_release": (c_uint32, [c_void_p, PathTicket]),
    "nl_default_path_budget": (PathBudget, []),
    "nl_path_process": (c_uint32, [c_void_p, POINTER(PathBudget), POINTER(c_uint32)]),
    "nl_path_take_finished": (c_uint32, [c_void_p, POINTER(PathFinished), c_uint32, POINTER(c_uint32), POINTER(c_uint32)]),
    "nl_path_get_queue_stats": (c_uint32, [c_void_p, POINTER(PathQueueStats)]),
    "nl_default_query_filter": (QueryFilterDef, []),
    "nl_navmesh_can_reach": (c_uint32, [c_void_p, NavmeshId, POINTER(QueryFilterDef), POINTER(c_uint32), POINTER(c_uint32),
                                c_uint32, POINTER(c_uint8)]),
    "nl_navmesh_get_reachable_polygons": (c_uint32, [c_void_p, NavmeshId, POINTER(QueryFilterDef), c_uint32,
                                             POINTER(c_uint32), c_uint32, POINTER(c_uint32)]),
    "nl_navmesh_get_islands": (c_uint32, [c_void_p, NavmeshId, POINTER(QueryFilterDef), POINTER(c_uint32), c_uint32,
                                  POINTER(c_uint32), POINTER(c_uint32)]),
    "nl_navmesh_raycast": (c_uint32, [c_void_p, NavmeshId, POINTER(QueryFilterDef), POINTER(NavmeshRay), c_uint32,
                              POINTER(NavmeshRaycastHit), POINTER(c_uint32), c_uint32]),
    "nl_navmesh_move_along_surface": (c_uint32, [c_void_p, NavmeshId, POINTER(QueryFilterDef), c_uint32, POINTER(c_float),
                                         POINTER(c_float), POINTER(NavPoint), POINTER(c_uint32), c_uint32,
                                         POINTER(c_uint32)]),
    "nl_default_random_points_def": (RandomPointsDef, []),
    "nl_navmesh_random_points": (c_uint32, [c_void_p, NavmeshId, POINTER(RandomPointsDef), POINTER(NavPoint), c_uint32,
                                    POINTER(c_uint32)]),
    "nl_default_agent_def": (AgentDef, []),
    "nl_agent_add": (c_uint32, [c_void_p, POINTER(AgentDef), POINTER(AgentId)]),
    "nl_agent_remove": (c_uint32, [c_void_p, AgentId]),
    "nl_agent_is_valid": (c_int32, [c_void_p, AgentId]),
    "nl_agent_set_destination": (c_uint32, [c_void_p, AgentId, POINTER(c_float)]),
    "nl_agent_stop": (c_uint32, [c_void_p, AgentId]),
    "nl_agent_teleport": (c_uint32, [c_void_p, AgentId, POINTER(c_float)]),
    "nl_agent_set_capabilities": (c_uint32, [c_void_p, AgentId, POINTER(AgentCapabilities)]),
    "nl_agent_set_speed": (c_uint32, [c_void_p, AgentId, c_float, c_float]),
    "nl_world_step": (c_uint32, [c_void_p, c_float]),
    "nl_agent_get_info": (c_uint32, [c_void_p, AgentId, POINTER(AgentInfo)]),
    "nl_world_get_agents": (c_uint32, [c_void_p, POINTER(AgentInfo), c_uint32, POINTER(c_uint32)]),
    "nl_agent_get_corners": (c_uint32, [c_void_p, AgentId, POINTER(PathPoint), c_uint32, POINTER(c_uint32)]),
    "nl_agent_get_trajectory": (c_uint32, [c_void_p, AgentId, POINTER(AgentTrajectory)]),
    "nl_world_get_agent_events": (c_uint32, [c_void_p, POINTER(AgentEvent), c_uint32, POINTER(c_uint32)]),
    "nl_plugin_load": (c_uint32, [c_void_p, c_char_p, POINTER(PluginId)]),
    "nl_plugin_get_description": (c_uint32, [c_void_p, PluginId, POINTER(PluginDescription)]),
    "nl_world_get_plugins": (c_uint32, [c_void_p, POINTER(PluginId), c_uint32, POINTER(c_uint32)]),
    "nl_default_recast_settings": (RecastSettings, []),
    "nl_plugin_register": (c_uint32, [c_void_p, PluginEntryFn, POINTER(PluginId)]),
}
