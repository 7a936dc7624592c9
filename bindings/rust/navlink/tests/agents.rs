//! Agents on the bridge level (tests/abi/agents_tests.c's): a jumper takes a generated jump across the gap
//! while a walker goes round by the bridge, as the states read in bulk and the step's events say; the
//! trajectory of the jump mid-flight; bad input refused. And a ferry (tests/core/world/surface_tests.cpp's):
//! walkers wait at a gangway for a shuttle, ride it across a chasm and get off on the far side, `AgentInfo`
//! saying which navmesh and carrier they stand on.
mod common;

use common::*;
use navlink::{
    default_agent_def, default_agent_type, default_link_def, status, sys,
    AgentEvent, AgentId, AgentInfo, AgentInfoExt, AgentType, LinkDef, LinkDefExt, LinkId, LinkKind, MeshFlags, MeshId, MeshOptions,
    NavmeshId, NavmeshInput, World, WorldOptions,
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
    assert!(def.height == 2.0 && def.max_speed == 3.5 && def.max_acceleration == 8.0 && def.avoidance);
    assert!((def.gravity - 9.81).abs() < 1e-6 && def.takeoff_speed == 0.0 && def.navmesh == NavmeshId::default());
    assert!(def.capabilities.radius == 0.6 && def.capabilities.max_jump_distance == 0.0);
    assert_eq!(def.give_up_seconds, 0.0);
    assert_eq!((navlink::AgentEventKind::Waiting.to_raw(), navlink::AgentReason::Crowd.to_raw()), (7, 8));
    assert_eq!(navlink::AgentReason::from_raw(sys::NL_AGENT_REASON_CROWD), navlink::AgentReason::Crowd);
    assert_eq!(navlink::AgentEventKind::from_raw(sys::NL_AGENT_EVENT_WAITING), navlink::AgentEventKind::Waiting);
    assert_eq!(WorldOptions::default().agent_paths_per_step, 32);
}

#[test]
fn walker_goes_round_and_jumper_jumps() {
    let world = World::new().unwrap();
    let navmesh = add_bridge_level(&world);
    assert!(world.links(navmesh).unwrap().iter().any(|l| l.kind == LinkKind::Jump), "jump links across the gap");
    let walker = add_agent(&world, navmesh, 1.0, 2.0, 0.0, 11);
    let jumper = add_agent(&world, navmesh, 1.0, 3.0, 3.0, 22);
    assert!(walker != jumper && world.is_agent_valid(walker));
    assert_eq!(world.agent_info(walker).unwrap().state, navlink::AgentState::Idle);
    let mut jumper_states = vec![world.agent_info(jumper).unwrap().state];
    world.set_agent_destination(walker, [9.0, 0.0, 2.0]).unwrap();
    world.set_agent_destination(jumper, [9.0, 0.0, 3.0]).unwrap();
    jumper_states.push(world.agent_info(jumper).unwrap().state);

    let mut events: Vec<AgentEvent> = Vec::new();
    let (mut walker_corners, mut jumper_corners) = (Vec::new(), Vec::new());
    let mut trajectory = None;
    let mut in_flight: Option<AgentInfo> = None;
    let mut walker_max_z = 0f32;
    let arrivals = |events: &[AgentEvent]| events.iter().filter(|e| e.kind == navlink::AgentEventKind::Arrived).count();
    for _ in 0..MAX_STEPS {
        if arrivals(&events) == 2 {
            break;
        }
        world.step(DT).unwrap();
        let step_events = world.agent_events().unwrap();
        if step_events.iter().any(|e| e.kind == navlink::AgentEventKind::PathReady) {
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
                if info.state == navlink::AgentState::Jumping {
                    in_flight = Some(*info);
                    if trajectory.is_none() {
                        trajectory = world.agent_trajectory(jumper).unwrap();
                    }
                }
            }
        }
    }

    for e in &events {
        assert_eq!(e.user_data, if e.agent == walker { 11 } else { 22 }, "{:?}", e);
    }
    let ready: Vec<&AgentEvent> = events.iter().filter(|e| e.kind == navlink::AgentEventKind::PathReady).collect();
    assert!(ready.len() == 2 && ready.iter().all(|e| e.reason == navlink::AgentReason::DestinationSet), "{:?}", ready);
    assert_eq!(arrivals(&events), 2);
    assert_eq!(world.agent_info(walker).unwrap().state, navlink::AgentState::Arrived);
    assert_eq!(world.agent_info(jumper).unwrap().state, navlink::AgentState::Arrived);

    // The walker takes no link: round by the bridge.
    assert!(!events.iter().any(|e| e.agent == walker && e.kind == navlink::AgentEventKind::LinkStarted));
    assert!(walker_max_z > 8.0, "the walker reached z {}", walker_max_z);
    assert!(walker_corners.len() >= 2 && walker_corners.iter().all(|p| p.segment == navlink::LinkKind::Walk), "{:?}", walker_corners);
    assert_eq!(jumper_corners.iter().filter(|p| p.segment == navlink::LinkKind::Jump).count(), 1, "{:?}", jumper_corners);

    // The jumper starts and finishes one generated jump.
    let of_jumper = |kind| events.iter().filter(|e| e.agent == jumper && e.kind == kind).collect::<Vec<_>>();
    let (started, finished) = (of_jumper(navlink::AgentEventKind::LinkStarted), of_jumper(navlink::AgentEventKind::LinkFinished));
    assert!(started.len() == 1 && finished.len() == 1 && started[0].link == finished[0].link, "{:?}", events);
    let jump = world.link(started[0].link).unwrap();
    assert!(jump.kind == LinkKind::Jump && jump.generated);
    let expected = [
        navlink::AgentState::Idle,
        navlink::AgentState::Waiting,
        navlink::AgentState::Walking,
        navlink::AgentState::Jumping,
        navlink::AgentState::Walking,
        navlink::AgentState::Arrived,
    ];
    assert!(is_subsequence(&expected, &jumper_states), "the jumper's states: {:?}", jumper_states);

    // Its trajectory, read in the air.
    let t = trajectory.expect("a trajectory while jumping");
    assert!(t.kind == navlink::TrajectoryKind::Arc && t.link == started[0].link, "{:?}", t);
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
    assert_eq!(world.agent_info(agent).unwrap().has_destination, false, "a refused destination is not kept");
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
    assert!(events.len() == 1 && events[0].kind == navlink::AgentEventKind::Failed && events[0].reason == navlink::AgentReason::NavmeshRemoved, "{:?}", events);
    assert_eq!(world.agent_info(agent).unwrap().state, navlink::AgentState::Failed);

    // A removed agent's id is stale everywhere.
    world.remove_agent(agent).unwrap();
    assert!(!world.is_agent_valid(agent) && world.agents().unwrap().is_empty());
    assert_fails(world.set_agent_destination(agent, [3.0, 0.0, 5.0]), status::INVALID_HANDLE, "nl_agent_set_destination");
    assert_fails(world.agent_info(agent), status::INVALID_HANDLE, "nl_agent_get_info");
    assert_fails(world.agent_trajectory(agent), status::INVALID_HANDLE, "nl_agent_get_trajectory");
    assert_fails(world.remove_agent(agent), status::INVALID_HANDLE, "nl_agent_remove");
}

/// The ferry: two 6 x 6 m ledges (boxes x in [0, 6] and [16, 22], z in [0, 6], tops y = 0) with one static
/// navmesh of their tops eroded 0.3 m (one quad each), and a 4 x 4 m movable box (top y = 0 in its own space,
/// x and z in [-2, 2]) carrying its top eroded 0.3 m, on a timetable: docked at the near ledge (centre
/// x = 8) for 3 s, 4 s across, docked at the far one (x = 14) for 3 s, 4 s back.
const FERRY_LEDGES: [f32; 24] = [
    0.3, 0.0, 0.3, 0.3, 0.0, 5.7, 5.7, 0.0, 5.7, 5.7, 0.0, 0.3, //
    16.3, 0.0, 0.3, 16.3, 0.0, 5.7, 21.7, 0.0, 5.7, 21.7, 0.0, 0.3,
];
const SHUTTLE_TOP: [f32; 12] = [-1.7, 0.0, -1.7, -1.7, 0.0, 1.7, 1.7, 0.0, 1.7, 1.7, 0.0, -1.7];
const NEAR_DOCK: f32 = 8.0;
const FAR_DOCK: f32 = 14.0;
const FERRY_GOAL: [f32; 3] = [20.0, 0.0, 3.0];

/// The shuttle's transform: its centre at (x, 0, 3) (column-major).
fn shuttle_at(x: f32) -> [f32; 16] {
    [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, x, 0.0, 3.0, 1.0]
}

/// The shuttle's centre x at time `t` of its 14 s timetable.
fn shuttle_x(t: f64) -> f32 {
    let (near, far) = (NEAR_DOCK as f64, FAR_DOCK as f64);
    let u = t % 14.0;
    (if u < 3.0 {
        near
    } else if u < 7.0 {
        near + (far - near) * (u - 3.0) / 4.0
    } else if u < 10.0 {
        far
    } else {
        far - (far - near) * (u - 10.0) / 4.0
    }) as f32
}

fn distance(a: [f32; 3], b: [f32; 3]) -> f32 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[test]
fn a_ferry_carries_walkers_across_a_chasm() {
    let world = World::new().unwrap();
    add_box(&world, [0.0, -1.0, 0.0], [6.0, 0.0, 6.0]);
    add_box(&world, [16.0, -1.0, 0.0], [22.0, 0.0, 6.0]);
    let at_far = MeshOptions { flags: MeshFlags::MOVABLE, transform: Some(shuttle_at(FAR_DOCK)), ..Default::default() };
    let shuttle = add_box_with(&world, [-2.0, -0.5, -2.0], [2.0, 0.0, 2.0], &at_far);
    let agent_type = AgentType { radius: 0.3, ..default_agent_type() };
    let ledges_input = NavmeshInput {
        polygon_vertex_counts: Some(&[4, 4]),
        agent_type,
        ..NavmeshInput::triangles(&FERRY_LEDGES, &[0, 1, 2, 3, 4, 5, 6, 7])
    };
    let ledges = world.add_navmesh(&ledges_input).unwrap();
    let deck_input = NavmeshInput {
        polygon_vertex_counts: Some(&[4]),
        agent_type,
        carrier: Some(shuttle),
        ..NavmeshInput::triangles(&SHUTTLE_TOP, &[0, 1, 2, 3])
    };
    let deck = world.add_navmesh(&deck_input).unwrap();
    // The gangways: manual cross links whose requirements are taken as given (all zero: a gap of 0, walked,
    // not jumped), each placed while the shuttle stands at its dock.
    let gangway = |navmesh: NavmeshId, start: [f32; 3], landing: NavmeshId, end: [f32; 3]| -> LinkId {
        let def = LinkDef { start, end, requirements_as_given: true, ..default_link_def() }.with_landing(Some(landing));
        assert_eq!((def.kind, def.requirements.gap), (LinkKind::Manual, 0.0));
        world.add_link(navmesh, &def).unwrap()
    };
    let leave = gangway(deck, [15.4, 0.0, 3.0], ledges, [16.6, 0.0, 3.0]);
    world.set_mesh_transform(shuttle, &shuttle_at(NEAR_DOCK)).unwrap();
    let board = gangway(ledges, [5.6, 0.0, 3.0], deck, [6.6, 0.0, 3.0]);
    assert_eq!((world.link(board).unwrap().holds, world.link(leave).unwrap().holds), (true, false));

    let walkers: Vec<AgentId> = [2.0, 4.0]
        .iter()
        .map(|&z| {
            let mut def = default_agent_def();
            def.navmesh = ledges;
            def.position = [2.0, 0.0, z];
            def.capabilities.radius = 0.3;
            let id = world.add_agent(&def).unwrap();
            world.set_agent_destination(id, FERRY_GOAL).unwrap();
            id
        })
        .collect();
    let first = world.agent_info(walkers[0]).unwrap();
    assert_eq!((first.navmesh, first.carrier_mesh(), first.carrier), (ledges, None, MeshId::default()), "on the near ledge");
    assert_eq!(first.carrier_position, first.position);

    let mut arrived: Vec<(AgentId, AgentInfo)> = Vec::new();
    let mut taken: Vec<(AgentId, LinkId)> = Vec::new();
    let (mut waited, mut riding) = (0, 0);
    let dt = 1.0 / 30.0;
    let mut t = 4.0f64; // the shuttle has just left: the first to reach the gangway waits for it
    for _ in 0..90 * 30 {
        if arrived.len() == walkers.len() {
            break;
        }
        t += dt;
        let x = shuttle_x(t);
        world.set_mesh_transform(shuttle, &shuttle_at(x)).unwrap();
        world.step(dt as f32).unwrap();
        for e in world.agent_events().unwrap() {
            assert_ne!(e.kind, navlink::AgentEventKind::Failed, "t {}: {:?}", t, e);
            if e.kind == navlink::AgentEventKind::LinkStarted {
                taken.push((e.agent, e.link));
            }
            if e.kind == navlink::AgentEventKind::Arrived {
                arrived.push((e.agent, world.agent_info(e.agent).unwrap()));
            }
        }
        for info in world.agents().unwrap() {
            if info.state == navlink::AgentState::Waiting && info.link == board {
                waited += 1;
            }
            let context = format!("t {}, the shuttle at x {}: {:?}", t, x, info);
            assert!(info.navmesh == ledges || info.navmesh == deck, "{}", context);
            if [navlink::AgentState::Jumping, navlink::AgentState::Falling, navlink::AgentState::Traversing].contains(&info.state) {
                // In the air over a cross link (both gangways are): flown in the world.
                assert!(distance(info.carrier_position, info.position) < 1e-3, "in the air: {}", context);
            } else if info.navmesh == deck {
                // On the deck: riding the shuttle, whose centre is at (x, 0, 3), unturned.
                riding += 1;
                assert_eq!(info.carrier_mesh(), Some(shuttle), "on the deck: {}", context);
                let mapped = [info.position[0] - x, info.position[1], info.position[2] - 3.0];
                assert!(distance(info.carrier_position, mapped) < 1e-3, "on the deck: {}", context);
            } else {
                assert_eq!(info.carrier_mesh(), None, "on a ledge: {}", context);
                assert!(distance(info.carrier_position, info.position) < 1e-3, "on a ledge: {}", context);
            }
        }
    }

    assert_eq!(arrived.len(), walkers.len(), "both arrived by t = {} s", t);
    assert!(waited > 0, "an agent waited at the gangway for the shuttle (WAITING, info.link)");
    assert!(riding > 0, "an agent stood on the shuttle's deck (navmesh, carrier, carrier_position)");
    for &walker in &walkers {
        assert!(taken.contains(&(walker, board)) && taken.contains(&(walker, leave)), "{:?} boarded and got off: {:?}", walker, taken);
        let (_, info) = arrived.iter().find(|(id, _)| *id == walker).expect("arrived");
        assert_eq!((info.state, info.navmesh, info.carrier_mesh()), (navlink::AgentState::Arrived, ledges, None), "{:?}", info);
        // Two bodies share the goal: they stand round it.
        assert!(horizontal_distance(info.position, FERRY_GOAL) < 1.5, "{:?}", info.position);
    }
}
