//! Navmeshes: built from the level by a builder plugin, or handed over by the host.
use crate::callbacks::{with_progress, Progress};
use crate::error::{check, Result};
use crate::level::c_string;
use crate::list::two_call;
use crate::types::{AgentType, BoundaryEdge, MeshId, NavPoint, NavPolygon, NavmeshId, NavmeshInfo, RecastSettings, TileCoord};
use crate::world::World;
use navlink_sys as sys;
use std::ops::{BitOr, BitOrAssign};
use std::os::raw::c_void;
use std::ptr;

/// What a navmesh build found wrong with its level (`NavmeshInfo::build_warnings`,
/// `nl_navmesh_info.build_warnings`), each also said in a warning in the log; the build still succeeded.
/// Bits this binding has no name for (a newer library's) are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct BuildWarnings(u32);

impl BuildWarnings {
    pub const NONE: BuildWarnings = BuildWarnings(0);
    /// Meshes look wound clockwise (`NavmeshInfo::turned_over_mesh_count`; `MeshFlags::CLOCKWISE`).
    pub const CLOCKWISE: BuildWarnings = BuildWarnings(sys::NL_BUILD_WARNING_CLOCKWISE);
    /// Meshes that did not say their units (`MeshOptions::metres_per_unit` 0) look given in other units than
    /// metres: walls more than 25 agents tall, or the whole level narrower than two.
    pub const UNITS: BuildWarnings = BuildWarnings(sys::NL_BUILD_WARNING_UNITS);
    /// Meshes that did not say their up axis (`MeshOptions::up_axis`) would hold more than 1.5 times the
    /// floor for the agent with z up.
    pub const Z_UP: BuildWarnings = BuildWarnings(sys::NL_BUILD_WARNING_Z_UP);

    pub const fn from_raw(raw: u32) -> Self {
        BuildWarnings(raw)
    }

    pub const fn to_raw(self) -> u32 {
        self.0
    }

    /// Every bit of `other` is set.
    pub const fn contains(self, other: BuildWarnings) -> bool {
        self.0 & other.0 == other.0
    }
}

impl BitOr for BuildWarnings {
    type Output = BuildWarnings;
    fn bitor(self, other: BuildWarnings) -> BuildWarnings {
        BuildWarnings(self.0 | other.0)
    }
}

impl BitOrAssign for BuildWarnings {
    fn bitor_assign(&mut self, other: BuildWarnings) {
        self.0 |= other.0;
    }
}

/// How to build a navmesh from the registered meshes: every static one, or one movable mesh (`carrier`);
/// meshes flagged `NOT_IN_NAVMESH` are left out, `OBSTACLE` ones only block, and each mesh's area goes to
/// the polygons over it. A level that looks wound clockwise, given in other units than metres or with z up
/// (where its meshes did not say: `MeshOptions::metres_per_unit`, `up_axis`) still builds: the log says why
/// in a warning, and `NavmeshInfo::build_warnings` has a bit for each.
#[derive(Clone, Copy, Debug)]
pub struct NavmeshBuild<'a> {
    pub agent_type: AgentType,
    /// The Recast builder's settings (`None`: its defaults).
    pub recast: Option<RecastSettings>,
    /// Settings as a JSON object, applied over `recast`.
    pub settings_json: Option<&'a str>,
    /// A navmesh-builder plugin's name; `None`: "recast".
    pub builder: Option<&'a str>,
    /// A movable mesh (`MeshFlags::MOVABLE`) to build on, alone and in its own space; the navmesh rides it.
    /// `None`: every static mesh (movable meshes are left out).
    pub carrier: Option<MeshId>,
}

impl<'a> NavmeshBuild<'a> {
    pub fn new(agent_type: AgentType) -> Self {
        NavmeshBuild { agent_type, recast: None, settings_json: None, builder: None, carrier: None }
    }
}

/// Height detail over the polygons, as Recast's detail mesh.
#[derive(Clone, Copy, Debug)]
pub struct NavmeshDetail<'a> {
    pub vertices: &'a [f32],
    pub triangles: &'a [u32],
    /// polygon_count + 1 offsets into the triangles.
    pub triangle_starts: &'a [u32],
}

/// A navmesh from the host's engine (`nl_navmesh_def`).
#[derive(Clone, Copy, Debug)]
pub struct NavmeshInput<'a> {
    pub vertices: &'a [f32],
    pub indices: &'a [u32],
    /// Corners of each polygon; `None`: triangles.
    pub polygon_vertex_counts: Option<&'a [u8]>,
    pub areas: Option<&'a [u8]>,
    pub weld_tolerance: f32,
    pub agent_type: AgentType,
    pub detail: Option<NavmeshDetail<'a>>,
    /// A movable mesh (`MeshFlags::MOVABLE`) the navmesh rides: the coordinates above are then in that mesh's
    /// own space, and `set_mesh_transform` moves the navmesh with it. `None`: world space, fixed. For
    /// `World::add_tile`, the navmesh's own carrier (another is refused).
    pub carrier: Option<MeshId>,
    /// The polygons are this tile of a grid (`World::add_tile`; `add_navmesh` then makes a tiled navmesh of this
    /// one tile, which `add_tile` grows). `None`: not a tile.
    pub tile: Option<NavmeshTile>,
}

/// Where a host's polygons go as one tile of a tiled navmesh (`nl_navmesh_def`'s tile fields): the tile
/// `coord` of a grid of squares `width` metres wide on the x-z plane whose tile (0, 0) has its lower corner at
/// `origin` (x, z). Tile (x, z) spans x in `[origin[0] + x * width, + width]` and z alike.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NavmeshTile {
    /// The tile's column (`x`) and row (`z`).
    pub coord: TileCoord,
    /// The squares' side, metres (> 0).
    pub width: f32,
    /// x and z of tile (0, 0)'s lower corner.
    pub origin: [f32; 2],
}

impl NavmeshTile {
    /// The tile at `coord` of a navmesh's grid (`NavmeshInfo::tile_width`, `tile_origin`).
    pub fn on_grid_of(info: &NavmeshInfo, coord: TileCoord) -> Self {
        NavmeshTile { coord, width: info.tile_width, origin: info.tile_origin }
    }
}

impl<'a> NavmeshInput<'a> {
    /// Triangles with the header's defaults (weld tolerance 1 mm, default agent).
    pub fn triangles(vertices: &'a [f32], indices: &'a [u32]) -> Self {
        let def = unsafe { sys::nl_default_navmesh_def() };
        NavmeshInput {
            vertices,
            indices,
            polygon_vertex_counts: None,
            areas: None,
            weld_tolerance: def.weld_tolerance,
            agent_type: def.agent_type,
            detail: None,
            carrier: None,
            tile: None,
        }
    }
}

/// Recast's usual agent: radius 0.6, height 2, climb 0.9, slope 45.
pub fn default_agent_type() -> AgentType {
    unsafe { sys::nl_default_agent_type() }
}

/// The Recast builder's defaults (`nl_default_recast_settings`); also `RecastSettings::default()`.
pub fn default_recast_settings() -> RecastSettings {
    RecastSettings::default()
}

impl World {
    pub fn build_navmesh(&self, build: &NavmeshBuild<'_>) -> Result<NavmeshId> {
        self.build_navmesh_reporting(build, None)
    }

    /// `build_navmesh`, telling `progress` of the build on this thread (fractions from 0 to 1, never going
    /// back, and the stage's name). Returning false cancels the build: an `Error` with CANCELLED, nothing
    /// added. A panic in `progress` cancels it too and resumes here.
    pub fn build_navmesh_with_progress(&self, build: &NavmeshBuild<'_>, progress: Progress<'_>) -> Result<NavmeshId> {
        self.build_navmesh_reporting(build, Some(progress))
    }

    fn build_navmesh_reporting(&self, build: &NavmeshBuild<'_>, progress: Option<Progress<'_>>) -> Result<NavmeshId> {
        let mut id = NavmeshId::default();
        with_build_def(build, progress, |def| unsafe { sys::nl_navmesh_build(self.raw(), def, &mut id) })?;
        Ok(id)
    }

    /// Builds again, from the level as it is now, the tiles of a tiled navmesh's grid whose squares overlap the
    /// box `[box_min, box_max]` seen from above (y is not read), with `build`'s builder and settings as
    /// `build_navmesh` takes them: they must make tiles of the navmesh's width (the same `tile_size` and
    /// `cell_size` it was built with), and `build.agent_type` must be the navmesh's; `build.carrier` is not read
    /// (the navmesh's level is). In one step a tile loaded there is replaced, one that comes out with no walkable
    /// surface is removed, the others are added. An `Error` with INVALID_ARGUMENT for a navmesh that is not tiled,
    /// a box not finite or with min > max (or of more than 2^22 tiles), another agent type, settings making another
    /// tile width, or no tile left; the builder's failures; nothing changed on a failure.
    pub fn build_tiles(&self, navmesh: NavmeshId, build: &NavmeshBuild<'_>, box_min: [f32; 3], box_max: [f32; 3]) -> Result<()> {
        self.build_tiles_reporting(navmesh, build, box_min, box_max, None)
    }

    /// `build_tiles`, telling `progress` of the build as `build_navmesh_with_progress` does: returning false
    /// cancels it (an `Error` with CANCELLED, nothing changed), and a panic in `progress` resumes here.
    pub fn build_tiles_with_progress(
        &self,
        navmesh: NavmeshId,
        build: &NavmeshBuild<'_>,
        box_min: [f32; 3],
        box_max: [f32; 3],
        progress: Progress<'_>,
    ) -> Result<()> {
        self.build_tiles_reporting(navmesh, build, box_min, box_max, Some(progress))
    }

    fn build_tiles_reporting(
        &self,
        navmesh: NavmeshId,
        build: &NavmeshBuild<'_>,
        box_min: [f32; 3],
        box_max: [f32; 3],
        progress: Option<Progress<'_>>,
    ) -> Result<()> {
        with_build_def(build, progress, |def| unsafe {
            sys::nl_navmesh_build_tiles(self.raw(), navmesh, def, box_min.as_ptr(), box_max.as_ptr())
        })
    }

    /// Adds the host's navmesh (copied, repaired as nl_navmesh_add says).
    pub fn add_navmesh(&self, input: &NavmeshInput<'_>) -> Result<NavmeshId> {
        let def = navmesh_def(input);
        let mut id = NavmeshId::default();
        check(unsafe { sys::nl_navmesh_add(self.raw(), &def, &mut id) })?;
        Ok(id)
    }

    pub fn remove_navmesh(&self, navmesh: NavmeshId) -> Result<()> {
        check(unsafe { sys::nl_navmesh_remove(self.raw(), navmesh) }).map(drop)
    }

    pub fn is_navmesh_valid(&self, navmesh: NavmeshId) -> bool {
        unsafe { sys::nl_navmesh_is_valid(self.raw(), navmesh) != 0 }
    }

    pub fn navmesh_info(&self, navmesh: NavmeshId) -> Result<NavmeshInfo> {
        let mut info = sys::nl_navmesh_info_init();
        check(unsafe { sys::nl_navmesh_get_info(self.raw(), navmesh, &mut info) })?;
        Ok(info.into())
    }

    /// The navmesh's vertices after welding.
    pub fn navmesh_vertices(&self, navmesh: NavmeshId) -> Result<Vec<[f32; 3]>> {
        two_call(|buffer: *mut [f32; 3], capacity, count| unsafe {
            sys::nl_navmesh_get_vertices(self.raw(), navmesh, buffer.cast(), capacity, count)
        })
    }

    pub fn polygon(&self, navmesh: NavmeshId, polygon: u32) -> Result<NavPolygon> {
        let mut out = sys::nl_nav_polygon_init();
        check(unsafe { sys::nl_navmesh_get_polygon(self.raw(), navmesh, polygon, &mut out) })?;
        Ok(out.into())
    }

    pub fn boundary_edges(&self, navmesh: NavmeshId) -> Result<Vec<BoundaryEdge>> {
        two_call(|buffer, capacity, count| unsafe {
            sys::nl_navmesh_get_boundary_edges(self.raw(), navmesh, buffer, capacity, count)
        })
    }

    /// Adds the host's polygons as a tile (`tile.tile`, which must be `Some`) of a tiled navmesh: one built with
    /// `RecastSettings::tile_size`, or added from a tile. The tile must be on the navmesh's grid
    /// (`NavmeshTile::on_grid_of` its info), made for its agent type, at a place no tile holds; the navmesh is
    /// joined again with it. An `Error` with INVALID_ARGUMENT otherwise (also for a navmesh that is not tiled),
    /// nothing changed. A tile's file (`save_tile`) is added with `add_tile_bytes` or `add_tile_file`.
    pub fn add_tile(&self, navmesh: NavmeshId, tile: &NavmeshInput<'_>) -> Result<()> {
        let def = navmesh_def(tile);
        check(unsafe { sys::nl_navmesh_add_tile(self.raw(), navmesh, &def) }).map(drop)
    }

    /// Removes the tile at `tile` from a tiled navmesh. An `Error` with NOT_FOUND (`ErrorKind::NotFound`) when
    /// no tile is loaded there (removed twice), INVALID_ARGUMENT for a navmesh that is not tiled or its last tile
    /// (remove the navmesh instead); nothing changed.
    pub fn remove_tile(&self, navmesh: NavmeshId, tile: TileCoord) -> Result<()> {
        check(unsafe { sys::nl_navmesh_remove_tile(self.raw(), navmesh, tile) }).map(drop)
    }

    /// The loaded tiles' places in row order (z, then x); empty for a navmesh that is not tiled.
    pub fn tiles(&self, navmesh: NavmeshId) -> Result<Vec<TileCoord>> {
        two_call(|buffer, capacity, count| unsafe { sys::nl_navmesh_get_tiles(self.raw(), navmesh, buffer, capacity, count) })
    }

    /// The navmesh point nearest each query point within the box `point +- half_extents`.
    pub fn find_nearest(&self, navmesh: NavmeshId, points: &[[f32; 3]], half_extents: [f32; 3]) -> Result<Vec<NavPoint>> {
        let mut out = vec![sys::nl_nav_point::default(); points.len()];
        check(unsafe {
            sys::nl_navmesh_find_nearest(
                self.raw(),
                navmesh,
                points.as_ptr().cast(),
                points.len() as u32,
                half_extents.as_ptr(),
                out.as_mut_ptr(),
            )
        })?;
        Ok(out.into_iter().map(NavPoint::from).collect())
    }

    pub fn navmeshes(&self) -> Result<Vec<NavmeshId>> {
        two_call(|buffer, capacity, count| unsafe { sys::nl_world_get_navmeshes(self.raw(), buffer, capacity, count) })
    }
}

/// `build` as an `nl_navmesh_build_def` (its builder's name and settings alive for the call), with `progress`'s
/// pair, handed to `call` (`build_navmesh`, `build_tiles`).
fn with_build_def(
    build: &NavmeshBuild<'_>,
    progress: Option<Progress<'_>>,
    call: impl FnOnce(&sys::nl_navmesh_build_def) -> u32,
) -> Result<()> {
    let builder = build.builder.map(|b| c_string(b.as_bytes(), "builder")).transpose()?;
    let mut def = unsafe { sys::nl_default_navmesh_build_def() };
    def.agent_type = build.agent_type;
    def.builder = builder.as_ref().map_or(ptr::null(), |b| b.as_ptr());
    let recast = build.recast.map(|r| r.to_c(unsafe { sys::nl_default_recast_settings() }));
    def.settings = recast.as_ref().map_or(ptr::null(), |r| r as *const sys::nl_recast_settings as *const c_void);
    if let Some(json) = build.settings_json {
        // A non-null pointer even for "", which is not a JSON object: the library says so.
        def.settings_json = if json.is_empty() { b"\0".as_ptr().cast() } else { json.as_ptr().cast() };
        def.settings_json_length = json.len();
    }
    def.carrier = build.carrier.unwrap_or_default();
    with_progress(progress, |function, user| {
        def.progress = function;
        def.progress_user = user;
        call(&def)
    })
}

/// `input` as an `nl_navmesh_def`, pointing into its slices (which outlive the def's use in the call).
fn navmesh_def(input: &NavmeshInput<'_>) -> sys::nl_navmesh_def {
    let mut def = unsafe { sys::nl_default_navmesh_def() };
    def.vertices = input.vertices.as_ptr();
    def.vertex_count = (input.vertices.len() / 3) as u32;
    def.indices = input.indices.as_ptr();
    def.polygon_vertex_counts = input.polygon_vertex_counts.map_or(ptr::null(), |c| c.as_ptr());
    def.polygon_count = input.polygon_vertex_counts.map_or(input.indices.len() / 3, |c| c.len()) as u32;
    def.areas = input.areas.map_or(ptr::null(), |a| a.as_ptr());
    def.weld_tolerance = input.weld_tolerance;
    def.agent_type = input.agent_type;
    if let Some(detail) = &input.detail {
        def.detail_vertices = detail.vertices.as_ptr();
        def.detail_vertex_count = (detail.vertices.len() / 3) as u32;
        def.detail_triangles = detail.triangles.as_ptr();
        def.detail_triangle_count = (detail.triangles.len() / 3) as u32;
        def.detail_triangle_starts = detail.triangle_starts.as_ptr();
    }
    def.carrier = input.carrier.unwrap_or_default();
    if let Some(tile) = &input.tile {
        def.tile_width = tile.width;
        def.tile_origin_x = tile.origin[0];
        def.tile_origin_z = tile.origin[1];
        def.tile_x = tile.coord.x;
        def.tile_z = tile.coord.z;
    }
    def
}
