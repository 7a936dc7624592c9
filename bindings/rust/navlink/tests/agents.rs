//! Agents on the bridge level (tests/abi/agents_test.c's): a jumper takes a generated jump across the gap
//! while a walker goes round by the bridge, as the states read in bulk and the step's events say; the
//! trajectory of the jump mid-flight; bad input refused.
mod common;

use common::*;
use navlink::{
    agent_event, agent_reason, agent_state, default_agent_def, link_kind, status, sys, trajectory_kind, AgentEvent, AgentId,
    AgentInfo, NavmeshId, World, WorldOptions,
};

const DT: f32 = 1.0 / 30.0;
const MAX_STEPS: usize = 30 * 20;

fn add_agent(world: &World, navmesh: NavmeshId, x: f32, z: f32, jump: f32, user_data: u64) -> AgentId {
    let mut def = default_agent_def();
    def.navmesh = navmesh;
    def.position = [x, 0.0, z];
    def.capabilities.radius = 0.3;
    def.capabilities.max_jump_distance = jump;
    def.capabilities.max_jump_height = if jump > 0.0 { 1.0 } else { 0.0 };
    def.user_data = user_data;
    world.add_agent(&def).unwrap()
}

/// True if every item of `expected` occurs in `actual`, in that order (others may come between).
fn is_subsequence<T: PartialEq>(expected: &[T], actual: &[T]) -> bool {
    let mut want = expected.iter().peekable();
    for item in actual {
        if want.peek() == Some(&item) {
            want.next();
        }
    }
    want.peek().is_none()
}

#[test]
fn defaults() {
    let def = default_agent_def();
    assert_eq!(def.size as usize, std::mem::size_of::<navlink::AgentDef>());
    assert!(def.height == 2.0 && def.max_speed == 3.5 && def.max_acceleration == 8.0 && def.avoidance == 1);
    assert!((def.gravity - 9.81).abs() < 1e-6 && def.takeoff_speed == 0.0 && def.navmesh == NavmeshId::default());
    assert!(def.capabilities.radius == 0.6 && def.capabilities.max_jump_distance == 0.0);
    assert_eq!(WorldOptions::default().agent_paths_per_step, 32);
}

#[test]
fn walker_goes_round_and_jumper_jumps() {
    let world = World::new().unwrap();
    let navmesh = add_bridge_level(&world);
    assert!(world.links(navmesh).unwrap().iter().any(|l| l.kind == link_kind::JUMP), "jump links across the gap");
    let walker = add_agent(&world, navmesh, 1.0, 2.0, 0.0, 11);
    let jumper = add_agent(&world, navmesh, 1.0, 3.0, 3.0, 22);
    assert!(walker != jumper && world.is_agent_valid(walker));
    assert_eq!(world.agent_info(walker).unwrap().state, agent_state::IDLE);
    let mut jumper_states = vec![world.agent_info(jumper).unwrap().state];
    world.set_agent_destination(walker, [9.0, 0.0, 2.0]).unwrap();
    world.set_agent_destination(jumper, [9.0, 0.0, 3.0]).unwrap();
    jumper_states.push(world.agent_info(jumper).unwrap().state);

    let mut events: Vec<AgentEvent> = Vec::new();
    let (mut walker_corners, mut jumper_corners) = (Vec::new(), Vec::new());
    let mut trajectory = None;
    let mut in_flight: Option<AgentInfo> = None;
    let mut walker_max_z = 0f32;
    let arrivals = |events: &[AgentEvent]| events.iter().filter(|e| e.kind == agent_event::ARRIVED).count();
    for _ in 0..MAX_STEPS {
        if arrivals(&events) == 2 {
            break;
        }
        world.step(DT).unwrap();
        let step_events = world.agent_events().unwrap();
        if step_events.iter().any(|e| e.kind == agent_event::PATH_READY) {
            walker_corners = world.agent_corners(walker).unwrap();
            jumper_corners = world.agent_corners(jumper).unwrap();
        }
        events.extend(step_events);
        let infos = world.agents().unwrap();
        assert_eq!(infos.len(), 2, "both agents listed after every step");
        for info in &infos {
            if info.id == walker {
                walker_max_z = walker_max_z.max(info.position[2]);
            } else if info.id == jumper {
                if Some(&info.state) != jumper_states.last() {
                    jumper_states.push(info.state);
                }
                if info.state == agent_state::JUMPING {
                    in_flight = Some(*info);
                    if trajectory.is_none() {
                        trajectory = world.agent_trajectory(jumper).unwrap();
                    }
                }
            }
        }
    }

    for e in &events {
        assert_eq!(e.size as usize, std::mem::size_of::<AgentEvent>());
        assert_eq!(e.user_data, if e.agent == walker { 11 } else { 22 }, "{:?}", e);
    }
    let ready: Vec<&AgentEvent> = events.iter().filter(|e| e.kind == agent_event::PATH_READY).collect();
    assert!(ready.len() == 2 && ready.iter().all(|e| e.reason == agent_reason::DESTINATION_SET), "{:?}", ready);
    assert_eq!(arrivals(&events), 2);
    assert_eq!(world.agent_info(walker).unwrap().state, agent_state::ARRIVED);
    assert_eq!(world.agent_info(jumper).unwrap().state, agent_state::ARRIVED);

    // The walker takes no link: round by the bridge.
    assert!(!events.iter().any(|e| e.agent == walker && e.kind == agent_event::LINK_STARTED));
    assert!(walker_max_z > 8.0, "the walker reached z {}", walker_max_z);
    assert!(walker_corners.len() >= 2 && walker_corners.iter().all(|p| p.segment == link_kind::WALK), "{:?}", walker_corners);
    assert_eq!(jumper_corners.iter().filter(|p| p.segment == link_kind::JUMP).count(), 1, "{:?}", jumper_corners);

    // The jumper starts and finishes one generated jump.
    let of_jumper = |kind| events.iter().filter(|e| e.agent == jumper && e.kind == kind).collect::<Vec<_>>();
    let (started, finished) = (of_jumper(agent_event::LINK_STARTED), of_jumper(agent_event::LINK_FINISHED));
    assert!(started.len() == 1 && finished.len() == 1 && started[0].link == finished[0].link, "{:?}", events);
    let jump = world.link(started[0].link).unwrap();
    assert!(jump.kind == link_kind::JUMP && jump.generated == 1);
    let expected = [
        agent_state::IDLE,
        agent_state::WAITING,
        agent_state::WALKING,
        agent_state::JUMPING,
        agent_state::WALKING,
        agent_state::ARRIVED,
    ];
    assert!(is_subsequence(&expected, &jumper_states), "the jumper's states: {:?}", jumper_states);

    // Its trajectory, read in the air.
    let t = trajectory.expect("a trajectory while jumping");
    assert!(t.kind == trajectory_kind::ARC && t.link == started[0].link, "{:?}", t);
    assert!(t.duration > 0.0 && t.elapsed >= 0.0 && t.elapsed <= t.duration, "{:?}", t);
    assert!(t.apex[1] > t.from[1].max(t.to[1]) && t.points[0] == t.from && t.points[3] == t.to, "{:?}", t);
    let in_flight = in_flight.unwrap();
    assert!(in_flight.link == t.link && (0.0..=1.0).contains(&in_flight.link_progress), "{:?}", in_flight);

    assert_eq!(world.agent_trajectory(jumper).unwrap(), None, "no trajectory on the ground");
    assert!(world.agent_corners(walker).unwrap().len() <= 1, "an arrived agent has no corners left");
}

#[test]
fn bad_input() {
    let refused = World::with_options(WorldOptions { agent_paths_per_step: 0, ..Default::default() });
    assert_fails(refused.map(drop), status::INVALID_ARGUMENT, "agent_paths_per_step");
    let world = World::with_options(WorldOptions { worker_count: 1, agent_paths_per_step: 1, ..Default::default() }).unwrap();
    let navmesh = add_bridge_level(&world);
    let agent = add_agent(&world, navmesh, 1.0, 2.0, 0.0, 0);
    let over_the_gap = [5.0, 0.0, 2.0];
    let off = navlink::AgentDef { navmesh, position: over_the_gap, ..default_agent_def() };
    assert_fails(world.add_agent(&off), status::NOT_FOUND, "def->position is not on the navmesh");
    assert_fails(world.set_agent_destination(agent, over_the_gap), status::NOT_FOUND, "nearest navmesh point");
    assert_eq!(world.agent_info(agent).unwrap().has_destination, 0, "a refused destination is not kept");
    assert_fails(world.set_agent_destination(agent, [f32::NAN, 0.0, 0.0]), status::INVALID_ARGUMENT, "point");
    assert_fails(world.step(f32::NAN), status::INVALID_ARGUMENT, "dt");
    assert_fails(world.set_agent_speed(agent, -1.0, 1.0), status::INVALID_ARGUMENT, "max_speed");
    let nan_radius = navlink::AgentCapabilities { radius: f32::NAN, ..walker() };
    assert_fails(world.set_agent_capabilities(agent, &nan_radius), status::INVALID_ARGUMENT, "radius");

    // A raw call must set the element size of its output array, as in C.
    let mut infos = [sys::nl_agent_info_init()];
    infos[0].size = 0;
    let mut count = 0;
    let refused = unsafe { sys::nl_world_get_agents(world.as_ptr(), infos.as_mut_ptr(), 1, &mut count) };
    assert!(sys::nl_failed(refused) && refused & status::INVALID_ARGUMENT != 0, "{:#x}", refused);

    // Its navmesh removed: the agent fails, with its event.
    world.set_agent_destination(agent, [3.0, 0.0, 5.0]).unwrap();
    world.step(0.1).unwrap();
    world.remove_navmesh(navmesh).unwrap();
    world.step(0.1).unwrap();
    let events = world.agent_events().unwrap();
    assert!(events.len() == 1 && events[0].kind == agent_event::FAILED && events[0].reason == agent_reason::NAVMESH_REMOVED, "{:?}", events);
    assert_eq!(world.agent_info(agent).unwrap().state, agent_state::FAILED);

    // A removed agent's id is stale everywhere.
    world.remove_agent(agent).unwrap();
    assert!(!world.is_agent_valid(agent) && world.agents().unwrap().is_empty());
    assert_fails(world.set_agent_destination(agent, [3.0, 0.0, 5.0]), status::INVALID_HANDLE, "nl_agent_set_destination");
    assert_fails(world.agent_info(agent), status::INVALID_HANDLE, "nl_agent_get_info");
    assert_fails(world.agent_trajectory(agent), status::INVALID_HANDLE, "nl_agent_get_trajectory");
    assert_fails(world.remove_agent(agent), status::INVALID_HANDLE, "nl_agent_remove");
}
