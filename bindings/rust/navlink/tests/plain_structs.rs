//! The plain structs that replaced navlink-sys's in the safe API (no `size`, no `reserved`): their
//! defaults are the header's, and what goes into the library comes back out with enums and bools.
mod common;

use common::*;
use navlink::{
    default_agent_type, default_link_def, default_recast_settings, sys, Link, LinkDef, LinkKind, LinkRequirements, MeshFlags,
    MeshOptions, NavmeshBuild, RecastPartition, RecastSettings, World,
};

#[test]
fn defaults_are_the_headers() {
    let c = unsafe { sys::nl_default_link_def() };
    let def = LinkDef::default();
    assert_eq!(def, default_link_def());
    assert_eq!(def, LinkDef::from(c));
    assert_eq!(def.kind, LinkKind::Manual);
    assert_eq!(def.kind.to_raw(), c.kind);
    assert_eq!((def.enabled, def.bidirectional, def.requirements_as_given), (c.enabled != 0, c.bidirectional != 0, c.requirements_as_given != 0));
    assert_eq!((def.cost_modifier, def.tolerance, def.landing_navmesh), (c.cost_modifier, c.tolerance, c.landing_navmesh));
    assert_eq!(def.requirements, LinkRequirements::default());

    let c = unsafe { sys::nl_default_recast_settings() };
    let recast = RecastSettings::default();
    assert_eq!(recast, default_recast_settings());
    assert_eq!(recast, RecastSettings::from(c));
    assert_eq!((recast.cell_size, recast.cell_height, recast.vertices_per_polygon), (c.cell_size, c.cell_height, c.vertices_per_polygon));
    assert_eq!(recast.partition.to_raw(), c.partition);
    assert_eq!(
        (recast.filter_low_hanging_obstacles, recast.filter_ledge_spans, recast.filter_walkable_low_height_spans),
        (c.filter_low_hanging_obstacles != 0, c.filter_ledge_spans != 0, c.filter_walkable_low_height_spans != 0)
    );
    assert_eq!(RecastPartition::from_raw(sys::NL_RECAST_PARTITION_MONOTONE), RecastPartition::Monotone);
}

#[test]
fn a_link_reads_back_as_given() {
    let world = World::new().unwrap();
    add_gap_level(&world);
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    let requirements = LinkRequirements { gap: 1.5, rise: 0.5, drop: 0.25, clearance_width: 0.75, abilities: 8, length: 9.0 };
    let def = LinkDef {
        start: [-5.0, 0.0, 4.0],
        end: [5.0, 0.0, 4.0],
        bidirectional: true,
        enabled: false,
        requirements_as_given: true,
        cost_modifier: 2.0,
        user_data: 11,
        requirements,
        ..LinkDef::default()
    };
    let id = world.add_link(navmesh, &def).unwrap();
    let link: Link = world.link(id).unwrap();
    assert_eq!(link.kind, LinkKind::Manual);
    assert!(link.bidirectional && !link.enabled && !link.generated && link.holds, "{:?}", link);
    assert_eq!((link.id, link.navmesh, link.cost_modifier, link.user_data), (id, navmesh, 2.0, 11));
    assert_eq!(link.requirements, requirements, "requirements as given");
    assert_eq!(world.links(navmesh).unwrap(), vec![link], "the list holds the same link");

    world.update_link(id, &LinkDef { bidirectional: false, enabled: true, requirements_as_given: false, ..def }).unwrap();
    let link = world.link(id).unwrap();
    assert!(!link.bidirectional && link.enabled);
    assert!((link.requirements.gap - 10.0).abs() < 1e-4 && link.requirements.abilities == 8, "measured from the ends: {:?}", link.requirements);
}

#[test]
fn recast_settings_reach_the_builder() {
    let world = World::new().unwrap();
    add_gap_level(&world);
    let monotone = RecastSettings { partition: RecastPartition::Monotone, filter_ledge_spans: false, ..RecastSettings::default() };
    let build = NavmeshBuild { recast: Some(monotone), ..NavmeshBuild::new(default_agent_type()) };
    assert!(world.navmesh_info(world.build_navmesh(&build).unwrap()).unwrap().polygon_count >= 2);
    let unknown = RecastSettings { partition: RecastPartition::Other(77), ..RecastSettings::default() };
    let refused = world.build_navmesh(&NavmeshBuild { recast: Some(unknown), ..build });
    assert!(refused.is_err(), "an unknown partition is refused: {:?}", refused);

}

#[test]
fn mesh_info_reads_back_flags_and_area() {
    let world = World::new().unwrap();
    let triangle = [0.0, 30.0, 0.0, 1.0, 30.0, 0.0, 0.0, 30.0, 1.0];
    let options = MeshOptions { flags: MeshFlags::MOVABLE | MeshFlags::CLOCKWISE, area: 3, user_data: 5, ..Default::default() };
    let mesh = world.add_mesh(&triangle, &[0, 1, 2], &options).unwrap();
    let info = world.mesh_info(mesh).unwrap();
    assert_eq!((info.flags, info.area, info.user_data, info.triangle_count), (options.flags, 3, 5, 1));
    assert_eq!(info.transform[0], 1.0, "identity");
}
