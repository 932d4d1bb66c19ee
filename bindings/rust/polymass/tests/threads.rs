//! Send/Sync where the C threading rules allow it, and concurrent use: one
//! mesh read by many threads at once, contexts moved between threads, free
//! functions from any thread, a context's own threads; every result
//! identical to a serial run.

mod common;

use common::*;
use polymass::{
    Body, Context, Diagnostics, Error, MassProperties, Mesh, Options, Positions, Surface,
};

fn assert_send_sync<T: Send + Sync>() {}
fn assert_send<T: Send>() {}

#[test]
fn thread_safety_markers() {
    assert_send_sync::<Mesh>();
    // Shared borrows of plain numbers: Send and Sync without an unsafe impl.
    assert_send_sync::<Surface<'static>>();
    assert_send_sync::<Positions<'static>>();
    assert_send_sync::<Options>();
    assert_send_sync::<MassProperties>();
    assert_send_sync::<Diagnostics>();
    assert_send_sync::<Error>();
    assert_send::<Context>(); // and not Sync: a compile_fail doc test of Context
}

const THREADS: usize = 4;
const ROUNDS: usize = 200;

fn bodies() -> Vec<Body> {
    (1..=ROUNDS).map(|i| Body::density(i as f64)).collect()
}

#[test]
fn one_mesh_read_by_many_threads_at_once() {
    let shape = cuboid([0.0; 3], [1.0, 2.0, 3.0])
        .with(&corner_tetrahedron(1.0, 2.0, 3.0).translated([4.0, 0.0, 0.0]));
    let mesh = Mesh::new(&shape.surface(), &Options::new()).unwrap();
    let bodies = bodies();
    let mut serial_context = Context::new().unwrap();
    let serial: Vec<MassProperties> = bodies
        .iter()
        .map(|body| serial_context.mesh_mass_properties(&mesh, body).unwrap())
        .collect();
    let diagnostics = mesh.diagnostics().unwrap();
    let shells = mesh.shells().unwrap();
    std::thread::scope(|scope| {
        let workers: Vec<_> = (0..THREADS)
            .map(|_| {
                let (mesh, bodies) = (&mesh, &bodies);
                scope.spawn(move || {
                    let mut context = Context::new().unwrap();
                    bodies
                        .iter()
                        .map(|body| context.mesh_mass_properties(mesh, body).unwrap())
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        // Meanwhile this thread asks the mesh its other questions.
        for _ in 0..ROUNDS {
            assert_eq!(mesh.diagnostics().unwrap(), diagnostics);
            assert_eq!(mesh.shells().unwrap(), shells);
        }
        for worker in workers {
            assert_eq!(worker.join().unwrap(), serial);
        }
    });
}

#[test]
fn meshes_and_contexts_move_between_threads() {
    let shape = triangular_prism(3.0, 2.0, 5.0);
    let mesh = Mesh::new(&shape.surface(), &Options::new()).unwrap();
    let context = Context::new().unwrap();
    let (mesh, mut context) = std::thread::spawn(move || (mesh, context)).join().unwrap();
    let p = context
        .mesh_mass_properties(&mesh, &Body::default())
        .unwrap();
    assert_matches(&p, &triangular_prism_exact(3.0, 2.0, 5.0), "moved mesh");
    // Dropped on another thread than the one that made them.
    std::thread::spawn(move || drop((mesh, context)))
        .join()
        .unwrap();
}

#[test]
fn free_functions_from_many_threads_with_shared_slices() {
    let shape = corner_tetrahedron(1.0, 2.0, 3.0);
    let surface = shape.surface();
    let exact = corner_tetrahedron_exact(1.0, 2.0, 3.0);
    std::thread::scope(|scope| {
        for _ in 0..THREADS {
            scope.spawn(|| {
                for _ in 0..ROUNDS {
                    let p = polymass::mass_properties(&surface, &Options::new(), &Body::default())
                        .unwrap();
                    assert_matches(&p, &exact, "tetrahedron");
                    let failure = polymass::polygon(&[[0.0, 0.0], [1.0, 0.0]]).unwrap_err();
                    // Each thread's message is its own call's.
                    assert!(failure.message().contains('2'), "{failure}");
                }
            });
        }
    });
}

#[test]
fn every_thread_count_gives_the_same_bits() {
    // Several blocks of faces.
    let (positions, triangles) = torus::torus(300, 250, 1e5);
    let surface = Surface::triangles(&positions, &triangles);
    let body = Body::density(7.5);
    let options = Options::new();
    let mut context = Context::new().unwrap();
    let one = context.mass_properties(&surface, &options, &body).unwrap();
    let one_mesh = context.mesh(&surface, &options).unwrap();
    let diagnostics = one_mesh.diagnostics().unwrap();
    assert_eq!(one_mesh.mass_properties(&body).unwrap(), one);
    for threads in [2, 3, 4, 7] {
        let mut many = Context::with_threads(threads).unwrap();
        assert_eq!(
            many.mass_properties(&surface, &options, &body).unwrap(),
            one
        );
        let mesh = many.mesh(&surface, &options).unwrap();
        assert_eq!(mesh.diagnostics().unwrap(), diagnostics);
        assert_eq!(many.mesh_mass_properties(&mesh, &body).unwrap(), one);
        let items = vec![(surface, options, body); 5];
        for result in many.batch(&items).unwrap() {
            assert_eq!(result.unwrap(), one);
        }
    }
    for out_of_range in [0, polymass_sys::POLYMASS_MAX_THREADS + 1] {
        let error = Context::with_threads(out_of_range).unwrap_err();
        assert_eq!(
            error.kind(),
            polymass::ErrorKind::InvalidArgument,
            "{error}"
        );
    }
}
