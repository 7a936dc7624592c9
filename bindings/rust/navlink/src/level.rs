//! Level geometry and batch ray queries.
use crate::error::{check, Error, Result};
use crate::kinds::UpAxis;
use crate::list::two_call;
use crate::types::{MeshId, MeshInfo, Ray, RayHit, Segment};
use crate::world::World;
use navlink_sys as sys;
use std::ffi::CString;
use std::ops::{BitOr, BitOrAssign};
use std::path::Path;
use std::ptr;

/// A mesh's flags (`nl_mesh_def.flags`, `nl_mesh_info.flags`), combined with `|`. Bits this binding has
/// no name for (a newer library's) are kept as they are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct MeshFlags(u32);

impl MeshFlags {
    pub const NONE: MeshFlags = MeshFlags(0);
    /// The mesh will move (`set_mesh_transform`); navmeshes can ride it.
    pub const MOVABLE: MeshFlags = MeshFlags(sys::NL_MESH_MOVABLE);
    /// Its fronts are wound clockwise (Godot's meshes): the triangles are turned over when registered.
    pub const CLOCKWISE: MeshFlags = MeshFlags(sys::NL_MESH_CLOCKWISE);
    /// In navmesh builds it only blocks: none of its triangles is walked on (crates, props).
    pub const OBSTACLE: MeshFlags = MeshFlags(sys::NL_MESH_OBSTACLE);
    /// Left out of navmesh builds (triggers, foliage); rays, link checks and agents still meet it.
    /// Not together with `OBSTACLE`.
    pub const NOT_IN_NAVMESH: MeshFlags = MeshFlags(sys::NL_MESH_NOT_IN_NAVMESH);

    pub const fn from_raw(raw: u32) -> Self {
        MeshFlags(raw)
    }

    pub const fn to_raw(self) -> u32 {
        self.0
    }

    /// Every bit of `other` is set.
    pub const fn contains(self, other: MeshFlags) -> bool {
        self.0 & other.0 == other.0
    }
}

impl BitOr for MeshFlags {
    type Output = MeshFlags;
    fn bitor(self, other: MeshFlags) -> MeshFlags {
        MeshFlags(self.0 | other.0)
    }
}

impl BitOrAssign for MeshFlags {
    fn bitor_assign(&mut self, other: MeshFlags) {
        self.0 |= other.0;
    }
}

/// What a mesh def carries besides geometry.
#[derive(Clone, Copy, Debug, Default)]
pub struct MeshOptions {
    /// `MeshFlags::MOVABLE` for meshes that will move; `CLOCKWISE`, `OBSTACLE`, `NOT_IN_NAVMESH`.
    pub flags: MeshFlags,
    /// Column-major 4x4 affine matrix (translation in 12, 13, 14); `None`: identity.
    pub transform: Option<[f32; 16]>,
    /// Returned by `mesh_info`, never interpreted.
    pub user_data: u64,
    /// The area navmesh builds give the polygons over this mesh (0..=`MESH_MAX_AREA`; the Recast builder
    /// carries 0..=62), priced by a path query's area costs. `mesh_info` reports it.
    pub area: u32,
    /// The length of one unit of the vertices in metres: 0.01 for centimetres (Unreal's, many exporters'),
    /// 0.0254 for inches, 1 for metres; 1e-6..=1e6. 0 (the default) means metres, not said: a navmesh build
    /// then warns when the level looks given in other units (`BuildWarnings::UNITS`); 1 says metres and
    /// silences it. Applied before `transform`, which is in metres as every other position and length.
    pub metres_per_unit: f32,
    /// Which axis of the vertices points up: `UpAxis::Z` turns z-up vertices to NavLink's y up, before
    /// `transform`. `UpAxis::NotSaid` (the default) reads them as y up and a navmesh build warns when the
    /// level looks z up (`BuildWarnings::Z_UP`).
    pub up_axis: UpAxis,
}

impl MeshOptions {
    fn def(&self) -> sys::nl_mesh_def {
        let mut def = unsafe { sys::nl_default_mesh_def() };
        def.flags = self.flags.to_raw();
        def.transform = self.transform.as_ref().map_or(ptr::null(), |t| t.as_ptr());
        def.user_data = self.user_data;
        def.area = self.area;
        def.metres_per_unit = self.metres_per_unit;
        def.up_axis = self.up_axis.to_raw();
        def
    }
}

pub(crate) fn c_string(s: &[u8], what: &str) -> Result<CString> {
    CString::new(s).map_err(|_| Error::binding(sys::NL_STATUS_INVALID_ARGUMENT, format!("{} contains a NUL byte", what)))
}

#[cfg(unix)]
pub(crate) fn path_bytes(path: &Path) -> Vec<u8> {
    use std::os::unix::ffi::OsStrExt;
    path.as_os_str().as_bytes().to_vec()
}

#[cfg(not(unix))]
pub(crate) fn path_bytes(path: &Path) -> Vec<u8> {
    path.to_string_lossy().into_owned().into_bytes()
}

impl World {
    /// Registers a triangle mesh (copied): x y z per vertex, three indices per triangle.
    pub fn add_mesh(&self, vertices: &[f32], indices: &[u32], options: &MeshOptions) -> Result<MeshId> {
        let mut def = options.def();
        def.vertices = vertices.as_ptr();
        def.vertex_count = (vertices.len() / 3) as u32;
        def.indices = indices.as_ptr();
        def.triangle_count = (indices.len() / 3) as u32;
        let mut id = MeshId::default();
        check(unsafe { sys::nl_mesh_add(self.raw(), &def, &mut id) })?;
        Ok(id)
    }

    /// Loads a Wavefront OBJ file as one mesh.
    pub fn add_obj_file(&self, path: impl AsRef<Path>, options: &MeshOptions) -> Result<MeshId> {
        let path = c_string(&path_bytes(path.as_ref()), "path")?;
        let def = options.def();
        let mut id = MeshId::default();
        check(unsafe { sys::nl_mesh_add_obj_file(self.raw(), path.as_ptr(), &def, &mut id) })?;
        Ok(id)
    }

    /// Registers OBJ text from memory as one mesh.
    pub fn add_obj_memory(&self, obj: &[u8], options: &MeshOptions) -> Result<MeshId> {
        let def = options.def();
        let mut id = MeshId::default();
        check(unsafe { sys::nl_mesh_add_obj_memory(self.raw(), obj.as_ptr().cast(), obj.len(), &def, &mut id) })?;
        Ok(id)
    }

    /// Removes a mesh (`INVALID_ARGUMENT` for a mesh a navmesh rides: remove the navmesh first).
    pub fn remove_mesh(&self, mesh: MeshId) -> Result<()> {
        check(unsafe { sys::nl_mesh_remove(self.raw(), mesh) }).map(drop)
    }

    /// Replaces a mesh's transform (column-major, affine, invertible). The navmeshes that ride the mesh
    /// move with it; such a mesh takes rotations and translations only (`INVALID_ARGUMENT` otherwise).
    pub fn set_mesh_transform(&self, mesh: MeshId, transform: &[f32; 16]) -> Result<()> {
        check(unsafe { sys::nl_mesh_set_transform(self.raw(), mesh, transform.as_ptr()) }).map(drop)
    }

    pub fn is_mesh_valid(&self, mesh: MeshId) -> bool {
        unsafe { sys::nl_mesh_is_valid(self.raw(), mesh) != 0 }
    }

    pub fn mesh_info(&self, mesh: MeshId) -> Result<MeshInfo> {
        let mut info = sys::nl_mesh_info_init();
        check(unsafe { sys::nl_mesh_get_info(self.raw(), mesh, &mut info) })?;
        Ok(info.into())
    }

    pub fn meshes(&self) -> Result<Vec<MeshId>> {
        two_call(|buffer, capacity, count| unsafe { sys::nl_world_get_meshes(self.raw(), buffer, capacity, count) })
    }

    /// Casts every ray into `hits` (one per ray; the first `rays.len()` are overwritten). The library
    /// writes `nl_ray_hit`s, copied into `hits`: this saves the caller's allocation, not the binding's.
    pub fn cast_rays_into(&self, rays: &[Ray], hits: &mut [RayHit]) -> Result<()> {
        if hits.len() < rays.len() {
            return Err(Error::binding(sys::NL_STATUS_INVALID_ARGUMENT, "cast_rays_into: fewer hits than rays".into()));
        }
        for (hit, c) in hits.iter_mut().zip(self.cast_rays_c(rays)?) {
            *hit = c.into();
        }
        Ok(())
    }

    pub fn cast_rays(&self, rays: &[Ray]) -> Result<Vec<RayHit>> {
        Ok(self.cast_rays_c(rays)?.into_iter().map(RayHit::from).collect())
    }

    fn cast_rays_c(&self, rays: &[Ray]) -> Result<Vec<sys::nl_ray_hit>> {
        // nl_ray_hit_init() sets the element size the library writes with.
        let mut hits = vec![sys::nl_ray_hit_init(); rays.len()];
        check(unsafe { sys::nl_world_cast_rays(self.raw(), rays.as_ptr(), rays.len() as u32, hits.as_mut_ptr()) })?;
        Ok(hits)
    }

    /// For each segment, whether any geometry lies between its ends.
    pub fn segments_blocked(&self, segments: &[Segment]) -> Result<Vec<bool>> {
        let mut blocked = vec![0u8; segments.len()];
        check(unsafe {
            sys::nl_world_segments_blocked(self.raw(), segments.as_ptr(), segments.len() as u32, blocked.as_mut_ptr())
        })?;
        Ok(blocked.into_iter().map(|b| b != 0).collect())
    }
}
