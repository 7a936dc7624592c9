//! From geometry to a path you wait for: two platforms 2 m apart, a navmesh, generated jump links, a
//! queued request for a body that jumps, waited for, then awaited as a future. Run with
//! `cargo run --example wait_for_path` (libnavlink found as navlink-sys's build.rs says).
use navlink::{default_agent_capabilities, default_agent_type, AgentCapabilities, MeshOptions, NavmeshBuild, PathQuery, World};
use std::time::Duration;

/// A box from `lo` to `hi`: corner k takes x from bit 0, y from bit 1, z from bit 2.
fn add_box(world: &World, lo: [f32; 3], hi: [f32; 3]) -> navlink::Result<navlink::MeshId> {
    let vertices: Vec<f32> = (0..8)
        .flat_map(|k| (0..3).map(move |axis| if k & (1 << axis) != 0 { hi[axis] } else { lo[axis] }))
        .collect();
    let indices = [0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6];
    world.add_mesh(&vertices, &indices, &MeshOptions::default())
}

fn main() -> navlink::Result<()> {
    let world = World::new()?;
    add_box(&world, [-11.0, -1.0, -5.0], [-1.0, 0.0, 5.0])?;
    add_box(&world, [1.0, -1.0, -5.0], [11.0, 0.0, 5.0])?;
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type()))?;
    world.generate_links(navmesh, None, None, None)?;
    let jumper = AgentCapabilities { max_jump_distance: 4.5, max_jump_height: 1.5, ..default_agent_capabilities() };
    let query = PathQuery::new(navmesh, [-6.0, 0.0, 0.0], [6.0, 0.0, 0.0], jumper);

    let request = world.request_path(&query)?;
    let outcome = request.wait(Some(Duration::from_secs(10)))?;
    let path = request.result()?.expect("finished");
    println!("waited: {:?}, {} points, {} link(s), {:.2} m", outcome, path.points.len(), path.summary.links_used, path.summary.length);
    for point in &path.points {
        println!("  {:?} from {:?}", point.segment, point.position);
    }
    drop(request); // releases the ticket

    // The same request as a future, driven here by the simplest executor: poll, park until woken.
    let awaited = block_on(world.request_path(&query)?)?;
    println!("awaited: {:?}, {} points", awaited.outcome(), awaited.points.len());
    Ok(())
}

fn block_on<F: std::future::Future + Unpin>(mut future: F) -> F::Output {
    struct Unpark(std::thread::Thread);
    impl std::task::Wake for Unpark {
        fn wake(self: std::sync::Arc<Self>) {
            self.0.unpark();
        }
    }
    let waker = std::task::Waker::from(std::sync::Arc::new(Unpark(std::thread::current())));
    let mut context = std::task::Context::from_waker(&waker);
    loop {
        if let std::task::Poll::Ready(output) = std::pin::Pin::new(&mut future).poll(&mut context) {
            return output;
        }
        std::thread::park();
    }
}
