//! Plugins: the built-in Recast builder listed, a navmesh builder written in Rust registered through
//! navlink-sys and used, loading failures.
mod common;

use common::*;
use navlink::sys;
use navlink::{default_agent_type, status, MeshOptions, NavmeshBuild, World};
use std::os::raw::{c_char, c_void};

const ROOF: &str = "rust-roof";
const NO_TRIANGLES: &[u8] = b"rust-roof: the level has no triangles\0";
const USED: &str = r#"{"at":"the highest vertex"}"#;

/// Covers the level's bounds with one square at its highest vertex (the C API guide's "roof" example).
unsafe extern "C" fn build_roof(
    _state: *mut c_void,
    host: *const sys::nl_plugin_host,
    def: *const sys::nl_navmesh_build_def,
    sink: sys::nl_navmesh_sink_fn,
    sink_context: *mut c_void,
) -> sys::nl_status {
    // Never unwind into the library.
    std::panic::catch_unwind(|| {
        let host = &*host;
        let get = host.get_level_triangles.expect("get_level_triangles");
        let (mut vertex_count, mut triangle_count) = (0u32, 0u32);
        let s = get(host.context, std::ptr::null_mut(), 0, &mut vertex_count, std::ptr::null_mut(), 0, &mut triangle_count);
        if sys::nl_failed(s) {
            return s;
        }
        if triangle_count == 0 {
            (host.set_error.expect("set_error"))(host.context, NO_TRIANGLES.as_ptr() as *const c_char);
            return sys::NL_STATUS_FAILURE | sys::NL_STATUS_NOT_FOUND;
        }
        let mut v = vec![0f32; 3 * vertex_count as usize];
        let mut t = vec![0u32; 3 * triangle_count as usize];
        let s = get(host.context, v.as_mut_ptr(), vertex_count, &mut vertex_count, t.as_mut_ptr(), triangle_count, &mut triangle_count);
        if sys::nl_failed(s) {
            return s;
        }
        let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
        for p in v.chunks(3) {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        // Counter-clockwise seen from above: (lo, lo) (lo, hi) (hi, hi) (hi, lo) in x-z.
        let quad = [lo[0], hi[1], lo[2], lo[0], hi[1], hi[2], hi[0], hi[1], hi[2], hi[0], hi[1], lo[2]];
        let square = [0u32, 1, 2, 3];
        let corners = [4u8];
        let mut navmesh = sys::nl_default_navmesh_def();
        navmesh.vertices = quad.as_ptr();
        navmesh.vertex_count = 4;
        navmesh.indices = square.as_ptr();
        navmesh.polygon_vertex_counts = corners.as_ptr();
        navmesh.polygon_count = 1;
        navmesh.agent_type = (*def).agent_type;
        if host.size as usize >= std::mem::size_of::<sys::nl_plugin_host>() {
            // A host that keeps what a build used.
            let s = (host.record_build_settings.expect("record_build_settings"))(host.context, USED.as_ptr() as *const c_char, USED.len());
            if sys::nl_failed(s) {
                return s;
            }
        }
        (sink.expect("sink"))(sink_context, &navmesh)
    })
    .unwrap_or(sys::NL_STATUS_FAILURE | sys::NL_STATUS_INTERNAL_ERROR)
}

unsafe extern "C" fn roof_entry(host_abi_version: u32, _host: *const sys::nl_plugin_host, info: *mut sys::nl_plugin_info) -> sys::nl_status {
    if host_abi_version < 1 {
        return sys::NL_STATUS_FAILURE | sys::NL_STATUS_VERSION_MISMATCH;
    }
    let info = &mut *info;
    info.abi_version = 1;
    info.name = b"rust-roof\0".as_ptr() as *const c_char;
    info.version = b"1.0\0".as_ptr() as *const c_char;
    info.description = b"one square over the whole level\0".as_ptr() as *const c_char;
    info.kinds = sys::NL_PLUGIN_NAVMESH_BUILDER;
    info.navmesh_builder.build = Some(build_roof);
    sys::NL_STATUS_SUCCESS
}

#[test]
fn plugins() {
    let world = World::new().unwrap();
    let builtin = world.plugins().unwrap();
    let recast = world.plugin_description(builtin[0]).unwrap();
    assert!(recast.name == "recast" && recast.builtin && recast.kinds & sys::NL_PLUGIN_NAVMESH_BUILDER != 0);

    let roof = unsafe { world.register_plugin(Some(roof_entry)) }.unwrap();
    let mine = world.plugin_description(roof).unwrap();
    assert!(mine.name == ROOF && !mine.builtin && mine.version == "1.0" && mine.abi_version == 1);
    assert_eq!(mine.kinds, sys::NL_PLUGIN_NAVMESH_BUILDER);
    assert_eq!(world.plugins().unwrap().len(), builtin.len() + 1);
    assert_fails(unsafe { world.register_plugin(Some(roof_entry)) }, status::INVALID_ARGUMENT, ROOF);

    let build = NavmeshBuild { builder: Some(ROOF), ..NavmeshBuild::new(default_agent_type()) };
    assert_fails(world.build_navmesh(&build), status::NOT_FOUND, "rust-roof: the level has no triangles");
    world.add_mesh(&[0.0, 0.0, 0.0, 0.0, 0.0, 4.0, 4.0, 0.5, 4.0], &[0, 1, 2], &MeshOptions::default()).unwrap();
    let navmesh = world.build_navmesh(&build).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    assert!(info.polygon_count == 1 && info.bounds_max[1] == 0.5 && info.bounds_max[0] == 4.0, "{:?}", info);
    let (_, made_for) = navlink::describe_navmesh_file(&world.save_navmesh(navmesh).unwrap()).unwrap();
    assert!(made_for.contains(&format!(r#""builder_settings":{}"#, USED)), "{}", made_for);

    assert_fails(unsafe { world.load_plugin("/no/such/plugin.so") }, status::NOT_FOUND, "nl_plugin_load");
}
