//! navlink-sys's plain-data structs (ids, rays, bodies: no `size`, no `reserved`) under Rust names, plain
//! Rust structs for the ones that carry `size` or `reserved`, and the header's constants grouped by meaning.
//! The first two are generated from the headers (plain_generated.rs, bindings/generate/emit_rust_plain.py);
//! what is here is what is not mechanical: the constants' Rust names, and the plain structs' tests.
pub use crate::plain_generated::*;

/// `nl_status` bits.
pub mod status {
    pub use navlink_sys::{
        NL_STATUS_BUFFER_TOO_SMALL as BUFFER_TOO_SMALL, NL_STATUS_CANCELLED as CANCELLED,
        NL_STATUS_FAILURE as FAILURE, NL_STATUS_INTERNAL_ERROR as INTERNAL_ERROR,
        NL_STATUS_INVALID_ARGUMENT as INVALID_ARGUMENT, NL_STATUS_INVALID_HANDLE as INVALID_HANDLE,
        NL_STATUS_IN_PROGRESS as IN_PROGRESS, NL_STATUS_IO_ERROR as IO_ERROR, NL_STATUS_NOT_FOUND as NOT_FOUND,
        NL_STATUS_OUT_OF_MEMORY as OUT_OF_MEMORY, NL_STATUS_PARSE_ERROR as PARSE_ERROR,
        NL_STATUS_PARTIAL_RESULT as PARTIAL_RESULT, NL_STATUS_SUCCESS as SUCCESS,
        NL_STATUS_VERSION_MISMATCH as VERSION_MISMATCH,
    };
}

pub use navlink_sys::{
    NL_AREA_EXCLUDED as AREA_EXCLUDED, NL_LINKS_LOAD_ANY_BODY as LINKS_LOAD_ANY_BODY, NL_MAX_WORKERS as MAX_WORKERS, NL_MESH_MAX_AREA as MESH_MAX_AREA,
    NL_NAVMESH_LOAD_SAME_LEVEL as NAVMESH_LOAD_SAME_LEVEL, NL_NO_ISLAND as NO_ISLAND, NL_NO_POLYGON as NO_POLYGON, NL_WORKERS_AUTO as WORKERS_AUTO,
};

#[cfg(test)]
mod tests {
    //! `to_c` over a C value with only `size` set rebuilds the C default: every field but `size` and
    //! `reserved` is mirrored, so nothing the header sets is lost on the way through the plain struct.
    use super::*;
    use crate::{LinkKind, MeshFlags, UpAxis};
    use navlink_sys as sys;

    #[test]
    fn link_def_default_is_the_c_default_whole() {
        let c = unsafe { sys::nl_default_link_def() };
        let plain = LinkDef::default();
        assert_eq!(plain.to_c(sys::nl_link_def { size: c.size, ..Default::default() }), c);
        assert_eq!((plain.kind, plain.enabled, plain.bidirectional, plain.requirements_as_given), (LinkKind::Manual, true, false, false));
        assert_eq!((plain.cost_modifier, plain.tolerance, plain.landing_navmesh), (1.0, 0.25, NavmeshId::default()));
    }

    #[test]
    fn recast_settings_default_is_the_c_default_whole() {
        let c = unsafe { sys::nl_default_recast_settings() };
        assert_eq!(RecastSettings::default().to_c(sys::nl_recast_settings { size: c.size, ..Default::default() }), c);
    }

    #[test]
    fn link_round_trips_with_every_field() {
        let mut c = sys::nl_link_init();
        c.kind = sys::NL_LINK_FIRST_PLUGIN_KIND + 4;
        c.id = LinkId { index1: 2, revision: 3 };
        c.navmesh = NavmeshId { index1: 1, revision: 1 };
        c.start = [1.0, 2.0, 3.0];
        c.end = [4.0, 5.0, 6.0];
        c.apex = [2.5, 7.0, 4.5];
        c.bidirectional = 1;
        c.generated = 1;
        c.enabled = 0;
        c.cost_modifier = 1.5;
        c.start_polygon = 7;
        c.end_polygon = 8;
        c.user_data = 99;
        c.requirements = sys::nl_link_requirements { gap: 1.0, rise: 2.0, drop: 3.0, clearance_width: 0.5, abilities: 6, length: 4.0, reserved: 0 };
        c.landing_navmesh = NavmeshId { index1: 5, revision: 2 };
        c.tolerance = 0.3;
        c.holds = 1;
        let plain = Link::from(c);
        assert_eq!(plain.kind, LinkKind::Other(sys::NL_LINK_FIRST_PLUGIN_KIND + 4));
        assert!(plain.kind.is_plugin() && plain.bidirectional && plain.generated && !plain.enabled && plain.holds);
        assert_eq!(plain.requirements.abilities, 6);
        assert_eq!(plain.to_c(sys::nl_link_init()), c);
    }

    #[test]
    fn output_structs_round_trip() {
        let mut hit = sys::nl_ray_hit_init();
        hit.distance = 2.0;
        hit.hit = 1;
        hit.mesh = MeshId { index1: 1, revision: 4 };
        assert_eq!(RayHit::from(hit).to_c(sys::nl_ray_hit_init()), hit);
        assert!(RayHit::from(hit).hit);

        let mut info = sys::nl_mesh_info_init();
        info.flags = sys::NL_MESH_MOVABLE | sys::NL_MESH_OBSTACLE | 0x100;
        info.area = 3;
        info.metres_per_unit = 0.01;
        info.up_axis = sys::NL_UP_AXIS_Z;
        let plain = MeshInfo::from(info);
        assert!(plain.flags.contains(MeshFlags::MOVABLE | MeshFlags::OBSTACLE) && plain.flags.to_raw() & 0x100 != 0);
        assert_eq!((plain.metres_per_unit, plain.up_axis), (0.01, UpAxis::Z));
        assert_eq!(plain.to_c(sys::nl_mesh_info_init()), info);

        let mut file = sys::nl_navmesh_file_info::default();
        file.rides_carrier = 1;
        file.level_hash = 0xfeed;
        let plain = NavmeshFileInfo::from(file);
        assert!(plain.rides_carrier);
        assert_eq!(plain.to_c(sys::nl_navmesh_file_info::default()), file);

        let point = sys::nl_nav_point { point: [1.0, 0.0, 2.0], distance: 0.5, polygon: 9, found: 1, beyond_box: 0, reserved: [0; 2] };
        assert!(NavPoint::from(point).found && !NavPoint::from(point).beyond_box);
        assert_eq!(NavPoint::from(point).to_c(sys::nl_nav_point::default()), point);
        let beyond = sys::nl_nav_point { found: 0, beyond_box: 1, polygon: sys::NL_NO_POLYGON, ..point };
        assert!(NavPoint::from(beyond).beyond_box);
        assert_eq!(NavPoint::from(beyond).to_c(sys::nl_nav_point::default()), beyond);

        let hit = sys::nl_navmesh_raycast_hit {
            hit: 1,
            t: 0.375,
            point: [2.0, 0.0, 0.5],
            wall_normal: [-1.0, 0.0, 0.0],
            end_polygon: 1,
            polygon_count: 2,
            ..sys::nl_navmesh_raycast_hit_init()
        };
        assert!(NavmeshRaycastHit::from(hit).hit);
        assert_eq!(NavmeshRaycastHit::from(hit).to_c(sys::nl_navmesh_raycast_hit_init()), hit);
    }
}
