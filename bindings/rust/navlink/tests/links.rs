//! Link generation on the gap level, manual links, JSON, progress closures.
mod common;

use common::*;
use navlink::{
    default_agent_capabilities, default_agent_type, default_link_def, link_settings_from_json, status, AgentCapabilities,
    AgentType, LinkKind, LinksLoadOptions, NavmeshBuild, NavmeshId, PathOutcome, PathQuery, World,
};

fn gap_world() -> (World, NavmeshId) {
    let world = World::new().unwrap();
    add_gap_level(&world);
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    (world, navmesh)
}

#[test]
fn generated_jump_links() {
    let (world, navmesh) = gap_world();
    let caller = std::thread::current().id();
    let mut fractions = Vec::new();
    let mut other_thread = 0;
    let mut progress = |fraction: f32, _stage: &str| {
        fractions.push(fraction);
        other_thread += (std::thread::current().id() != caller) as i32;
        true
    };
    let report = world.generate_links(navmesh, None, None, Some(&mut progress)).unwrap();
    let links = world.links(navmesh).unwrap();
    assert!(report.jump_links >= 5 && report.drop_links == 0 && links.len() as u32 == report.jump_links, "{:?}", report);
    for l in &links {
        assert!(l.kind == LinkKind::Jump && l.generated && l.bidirectional && l.navmesh == navmesh);
        assert!((l.requirements.gap - 2.0).abs() <= 0.05, "the gap is rim to rim: {}", l.requirements.gap);
        assert!(l.requirements.length >= 3.1 && l.requirements.length <= 3.9);
        assert!((l.requirements.length - horizontal_distance(l.start, l.end)).abs() < 1e-3);
        assert!(l.start[0].min(l.end[0]) < -1.0 && l.start[0].max(l.end[0]) > 1.0, "one end on each platform");
        assert!(l.apex[1] > l.start[1].max(l.end[1]), "the apex is above the ends");
    }
    assert!(fractions.len() >= 2 && *fractions.last().unwrap() == 1.0 && other_thread == 0);

    // Settings from JSON: a max_jump_gap below the gap leaves nothing to jump.
    let short = link_settings_from_json("{\"max_jump_gap\": 1.8}", None).unwrap();
    assert_eq!(short.max_jump_gap, 1.8);
    let none = world.generate_links(navmesh, Some(&short), None, None).unwrap();
    assert!(none.jump_links == 0 && none.rejected_distance > 0 && world.links(navmesh).unwrap().is_empty());
    assert_fails(link_settings_from_json("{\"max_link_dist\": 3}", None), status::INVALID_ARGUMENT, "max_link_dist");

    // Cancelling leaves the links as they were; a panic cancels and resumes in the caller.
    world.generate_links(navmesh, None, None, None).unwrap();
    let before = world.links(navmesh).unwrap();
    assert_fails(world.generate_links(navmesh, None, None, Some(&mut |_, _| false)), status::CANCELLED, "");
    assert_eq!(world.links(navmesh).unwrap(), before, "a cancelled generation changes nothing");
    let panicked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let _ = world.generate_links(navmesh, None, None, Some(&mut |_, _| panic!("progress panics")));
    }));
    assert!(panicked.is_err(), "the closure's panic comes back to the caller");
    assert_eq!(world.links(navmesh).unwrap(), before, "and the generation was cancelled");

    // A wall in the gap: the update in its box removes every jump, as a full generation would.
    add_box(&world, [-0.1, -20.0, -6.0], [0.1, 6.0, 6.0]);
    let walled = world.update_links_in_box(navmesh, [-0.2, -21.0, -7.0], [0.2, 7.0, 7.0], None).unwrap();
    assert!(walled.jump_links == 0 && world.links(navmesh).unwrap().is_empty(), "{:?}", walled);
    assert_eq!(world.remove_generated_links(navmesh).unwrap(), 0);
}

#[test]
fn manual_links_and_json() {
    let (world, navmesh) = gap_world();
    world.generate_links(navmesh, None, None, None).unwrap();
    let generated = world.links(navmesh).unwrap().len() as u32;

    let mut def = default_link_def();
    assert!(def.kind == LinkKind::Manual && def.enabled && def.cost_modifier == 1.0 && !def.requirements_as_given);
    def.start = [-5.0, 0.0, 4.0];
    def.end = [5.0, 0.0, 4.0];
    def.user_data = 7;
    def.requirements.gap = 99.0; // measured from the ends instead
    let manual = world.add_link(navmesh, &def).unwrap();
    let got = world.link(manual).unwrap();
    assert!(got.kind == LinkKind::Manual && !got.generated && got.user_data == 7 && got.id == manual && got.navmesh == navmesh);
    assert!((got.requirements.gap - 10.0).abs() < 1e-4, "the gap is measured from the ends: {}", got.requirements.gap);

    // Requirements taken as given: a link across the gap that asks only for an ability.
    let mut ability = default_link_def();
    ability.start = [-5.0, 0.0, -4.0];
    ability.end = [5.0, 0.0, -4.0];
    ability.requirements_as_given = true;
    ability.requirements.abilities = 4;
    let ability_link = world.add_link(navmesh, &ability).unwrap();
    let r = world.link(ability_link).unwrap().requirements;
    assert!(r.gap == 0.0 && r.rise == 0.0 && r.abilities == 4 && (r.length - 10.0).abs() < 1e-4,
            "requirements as given, the length of 0 measured: {:?}", r);
    let able = AgentCapabilities { abilities: 4, ..default_agent_capabilities() };
    let across = world.find_path(&PathQuery::new(navmesh, WEST, EAST, able)).unwrap();
    assert!(across.outcome() == PathOutcome::Complete && across.points.iter().any(|p| p.link == ability_link),
            "a walker with the ability crosses on that link: {:?}", across.outcome());
    let stuck = world.find_path(&PathQuery::new(navmesh, WEST, EAST, default_agent_capabilities())).unwrap();
    assert_eq!(stuck.outcome(), PathOutcome::Partial, "a walker without it does not");
    world.remove_link(ability_link).unwrap();
    def.enabled = false;
    world.update_link(manual, &def).unwrap();
    assert!(!world.link(manual).unwrap().enabled);

    assert_eq!(world.remove_generated_links(navmesh).unwrap(), generated);
    assert_eq!(world.links(navmesh).unwrap().len(), 1);
    world.generate_links(navmesh, None, None, None).unwrap();
    let json = world.save_links_json(navmesh).unwrap();
    assert!(json.contains("navlink-links"));
    assert_eq!(world.load_links_json(navmesh, &json, &LinksLoadOptions::default()).unwrap(), generated + 1);
    assert!(!world.is_link_valid(manual), "loaded links get new ids");
    assert_fails(world.link(manual), status::INVALID_HANDLE, "nl_link_get");
    assert_fails(world.remove_link(manual), status::INVALID_HANDLE, "nl_link_remove");
    assert_fails(world.load_links_json(navmesh, "[1,", &LinksLoadOptions::default()), status::PARSE_ERROR, "nl_navmesh_load_links_json");
    def.end = [0.0, 0.0, 0.0]; // over the gap: off the navmesh
    assert_fails(world.add_link(navmesh, &def), status::INVALID_ARGUMENT, "def->end");
}

#[test]
fn links_json_for_another_body() {
    let (world, logged) = world_keeping_log();
    add_gap_level(&world);
    let wide = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap(); // radius 0.6
    world.generate_links(wide, None, None, None).unwrap();
    let mut def = default_link_def();
    def.start = [-5.0, 0.0, 4.0];
    def.end = [5.0, 0.0, 4.0];
    world.add_link(wide, &def).unwrap();
    let count = world.links(wide).unwrap().len() as u32;
    let json = world.save_links_json(wide).unwrap();
    assert!(json.contains("\"made_for\""), "the saved JSON records what its links were made for");

    let slim = AgentType { radius: 0.3, ..default_agent_type() };
    let narrow = world.build_navmesh(&NavmeshBuild::new(slim)).unwrap();
    let refused = world.load_links_json(narrow, &json, &LinksLoadOptions::default()).unwrap_err();
    assert!(refused.has(status::FAILURE) && refused.has(status::INVALID_ARGUMENT), "{}", refused);
    assert!(refused.message().contains("radius 0.6") && refused.message().contains("radius 0.3"),
            "both bodies named: {}", refused.message());
    assert!(world.links(narrow).unwrap().is_empty(), "a refused load changes nothing");
    logged.lock().unwrap().clear();
    let any_body = LinksLoadOptions { any_body: true };
    assert_eq!(world.load_links_json(narrow, &json, &any_body).unwrap(), count, "any_body loads them all");
    assert_eq!(world.links(narrow).unwrap().len() as u32, count);
    {
        let logged = logged.lock().unwrap();
        assert!(logged.iter().any(|m| m.contains("radius 0.6") && m.contains("radius 0.3")),
                "any_body warns to the log, naming both bodies: {:?}", logged);
    }

    let same = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    assert_eq!(world.load_links_json(same, &json, &LinksLoadOptions::default()).unwrap(), count, "the same body loads them");
    assert_eq!(world.load_links_json(wide, &json, &LinksLoadOptions::default()).unwrap(), count);
}
