//! Baked navmesh files: a navmesh, its links and what they were made for, saved as bytes or a file and
//! loaded with no Recast build; a tiled navmesh's tiles saved and added one by one (tiles' files).
use crate::error::{check, Error, Result};
use crate::level::{c_string, path_bytes};
use crate::types::{MeshId, NavmeshFileInfo, NavmeshId, TileCoord};
use crate::world::World;
use navlink_sys as sys;
use std::os::raw::c_void;
use std::path::Path;
use std::ptr;

/// How to load a navmesh file (`nl_navmesh_load_def`). `Default`: no carrier, whatever the level.
#[derive(Clone, Copy, Debug, Default)]
pub struct NavmeshLoadOptions {
    /// For a file whose navmesh rode a movable mesh (`NavmeshFileInfo::rides_carrier`): the movable mesh
    /// it rides now. `None` otherwise.
    pub carrier: Option<MeshId>,
    /// Refuse (`INVALID_ARGUMENT`) a file baked from other level geometry than the world holds now
    /// (`NAVMESH_LOAD_SAME_LEVEL`: the level hashes differ).
    pub same_level: bool,
}

impl NavmeshLoadOptions {
    /// The C def: the header's defaults (`nl_default_navmesh_load_def`) with these options.
    fn def(&self) -> sys::nl_navmesh_load_def {
        let mut def = unsafe { sys::nl_default_navmesh_load_def() };
        def.carrier = self.carrier.unwrap_or_default();
        if self.same_level {
            def.flags |= sys::NL_NAVMESH_LOAD_SAME_LEVEL;
        }
        def
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_options_are_the_c_default_def() {
        assert_eq!(NavmeshLoadOptions::default().def(), unsafe { sys::nl_default_navmesh_load_def() });
        let options = NavmeshLoadOptions { carrier: Some(MeshId { index1: 3, revision: 1 }), same_level: true };
        let def = options.def();
        assert_eq!((def.carrier, def.flags), (MeshId { index1: 3, revision: 1 }, sys::NL_NAVMESH_LOAD_SAME_LEVEL));
    }
}

/// Reads a navmesh file's bytes without loading it (no world needed): what it holds, and what it was made
/// for as a JSON object (`{"builder", "builder_settings", "link_settings", "link_plugins", "level_hash", "writer"}`).
/// `VERSION_MISMATCH` (not a NavLink navmesh file, or a newer format), `PARSE_ERROR` (truncated or corrupted).
pub fn describe_navmesh_file(data: &[u8]) -> Result<(NavmeshFileInfo, String)> {
    let mut info = sys::nl_navmesh_file_info::default(); // size set
    let mut length = 0usize;
    check(unsafe {
        sys::nl_navmesh_file_describe(data.as_ptr().cast(), data.len(), &mut info, ptr::null_mut(), 0, &mut length)
    })?;
    let mut buffer = vec![0u8; length + 1];
    check(unsafe {
        sys::nl_navmesh_file_describe(
            data.as_ptr().cast(),
            data.len(),
            ptr::null_mut(),
            buffer.as_mut_ptr().cast(),
            buffer.len(),
            &mut length,
        )
    })?;
    buffer.truncate(length);
    let json = String::from_utf8(buffer)
        .map_err(|_| Error::binding(sys::NL_STATUS_INTERNAL_ERROR, "made-for JSON is not UTF-8".into()))?;
    Ok((NavmeshFileInfo::from(info), json))
}

impl World {
    /// The navmesh, its links (generated and manual, in `links` order) and what they were made for, as a
    /// navmesh file's bytes. `INVALID_ARGUMENT` for a navmesh with cross links (a file holds one navmesh's
    /// own links).
    pub fn save_navmesh(&self, navmesh: NavmeshId) -> Result<Vec<u8>> {
        loop {
            let mut size = 0usize;
            check(unsafe { sys::nl_navmesh_save(self.raw(), navmesh, ptr::null_mut(), 0, &mut size) })?;
            let mut buffer = vec![0u8; size];
            let status = unsafe {
                sys::nl_navmesh_save(self.raw(), navmesh, buffer.as_mut_ptr() as *mut c_void, buffer.len(), &mut size)
            };
            if sys::nl_failed(status) && status & sys::NL_STATUS_BUFFER_TOO_SMALL != 0 {
                continue; // the links changed between the two calls
            }
            check(status)?;
            buffer.truncate(size);
            return Ok(buffer);
        }
    }

    /// `save_navmesh` written to the file at `path`, whole or not at all. `IO_ERROR`: cannot write.
    pub fn save_navmesh_file(&self, navmesh: NavmeshId, path: impl AsRef<Path>) -> Result<()> {
        let path = c_string(&path_bytes(path.as_ref()), "path")?;
        check(unsafe { sys::nl_navmesh_save_file(self.raw(), navmesh, path.as_ptr()) }).map(drop)
    }

    /// Adds the navmesh and its links held in a navmesh file's bytes (new ids); a tile's file (`save_tile`) makes
    /// a tiled navmesh of that one tile, which `add_tile_bytes` grows. `VERSION_MISMATCH` (not a NavLink navmesh
    /// file, or a newer format), `PARSE_ERROR` (truncated or corrupted), `INVALID_ARGUMENT` (a carrier for a file
    /// that rode none or none for one that did; `same_level` and the level differs; polygons or links that do
    /// not fit). Nothing is added on failure.
    pub fn load_navmesh(&self, data: &[u8], options: &NavmeshLoadOptions) -> Result<NavmeshId> {
        let def = options.def();
        let mut id = NavmeshId::default();
        check(unsafe { sys::nl_navmesh_load(self.raw(), data.as_ptr().cast(), data.len(), &def, &mut id) })?;
        Ok(id)
    }

    /// `load_navmesh` from the file at `path`; also `NOT_FOUND` (no such file) and `IO_ERROR`.
    pub fn load_navmesh_file(&self, path: impl AsRef<Path>, options: &NavmeshLoadOptions) -> Result<NavmeshId> {
        let path = c_string(&path_bytes(path.as_ref()), "path")?;
        let def = options.def();
        let mut id = NavmeshId::default();
        check(unsafe { sys::nl_navmesh_load_file(self.raw(), path.as_ptr(), &def, &mut id) })?;
        Ok(id)
    }

    /// One tile of a tiled navmesh as a tile's file's bytes: the tile's polygons as built or added, the generated
    /// links it owns (those that start on it, wherever they end), what it was made for, and its content hash
    /// (`tile_hash`); host links are not in it (`save_navmesh` saves a whole navmesh with them). Load the first
    /// tile of a world with `load_navmesh` (a tiled navmesh of that tile) and the others with `add_tile_bytes`,
    /// in any order: the navmesh and links are those the tiles were saved from. An `Error` with NOT_FOUND
    /// (`ErrorKind::NotFound`) when no tile is loaded there, INVALID_ARGUMENT for a navmesh that is not tiled or
    /// rides a movable mesh (save it whole).
    pub fn save_tile(&self, navmesh: NavmeshId, tile: TileCoord) -> Result<Vec<u8>> {
        loop {
            let mut size = 0usize;
            check(unsafe { sys::nl_navmesh_save_tile(self.raw(), navmesh, tile, ptr::null_mut(), 0, &mut size) })?;
            let mut buffer = vec![0u8; size];
            let status = unsafe {
                sys::nl_navmesh_save_tile(self.raw(), navmesh, tile, buffer.as_mut_ptr() as *mut c_void, buffer.len(), &mut size)
            };
            if sys::nl_failed(status) && status & sys::NL_STATUS_BUFFER_TOO_SMALL != 0 {
                continue; // the tile or its links changed between the two calls
            }
            check(status)?;
            buffer.truncate(size);
            return Ok(buffer);
        }
    }

    /// `save_tile` written to the file at `path`, whole or not at all. `IO_ERROR`: cannot write.
    pub fn save_tile_file(&self, navmesh: NavmeshId, tile: TileCoord, path: impl AsRef<Path>) -> Result<()> {
        let path = c_string(&path_bytes(path.as_ref()), "path")?;
        check(unsafe { sys::nl_navmesh_save_tile_file(self.raw(), navmesh, tile, path.as_ptr()) }).map(drop)
    }

    /// Adds the tile a tile's file's bytes hold (`save_tile`) to a tiled navmesh, with its links, as `add_tile` adds
    /// a tile; no link is generated: a link to a tile not loaded waits, out of every path, until that tile is
    /// added. `VERSION_MISMATCH` (not a NavLink navmesh file, or a newer format), `PARSE_ERROR` (truncated or
    /// corrupted), `INVALID_ARGUMENT` (a whole navmesh's file; a tile of another grid or agent type, or made with
    /// another builder, builder settings or link settings than the navmesh; a tile already loaded there; polygons
    /// or links that do not fit). Nothing changed on failure.
    pub fn add_tile_bytes(&self, navmesh: NavmeshId, data: &[u8]) -> Result<()> {
        check(unsafe { sys::nl_navmesh_add_tile_bytes(self.raw(), navmesh, data.as_ptr().cast(), data.len()) }).map(drop)
    }

    /// `add_tile_bytes` from the file at `path`; also `NOT_FOUND` (no such file) and `IO_ERROR`.
    pub fn add_tile_file(&self, navmesh: NavmeshId, path: impl AsRef<Path>) -> Result<()> {
        let path = c_string(&path_bytes(path.as_ref()), "path")?;
        check(unsafe { sys::nl_navmesh_add_tile_file(self.raw(), navmesh, path.as_ptr()) }).map(drop)
    }

    /// The content hash of the tile at `tile` of a tiled navmesh's grid (loaded or not), from what the world holds
    /// now: the level's triangles in the columns the tile, its links and its neighbours' borders reach, the
    /// builder and its settings, the link settings and the body. A tile's file records the hash it was saved with
    /// (`NavmeshFileInfo::content_hash`): a bake skips a tile whose hash it holds. Never 0. `INVALID_ARGUMENT` for
    /// a navmesh that is not tiled.
    pub fn tile_hash(&self, navmesh: NavmeshId, tile: TileCoord) -> Result<u64> {
        let mut hash = 0u64;
        check(unsafe { sys::nl_navmesh_get_tile_hash(self.raw(), navmesh, tile, &mut hash) })?;
        Ok(hash)
    }
}
