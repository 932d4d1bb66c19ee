//! A batch gives each surface its single call's result, bit for bit, each
//! with its own options, and keeps each failure to its own item.

mod common;

use common::*;
use polymass::{Body, ErrorKind, Options, Warnings};

#[test]
fn batch_equals_single_calls_and_keeps_errors_apart() {
    let block = cuboid([0.0; 3], [2.0, 1.0, 0.5]).translated([1e6, 0.0, 0.0]);
    let tetra = corner_tetrahedron(1.0, 2.0, 0.75);
    let inverted = tetra.reversed();
    let accepting = Options::new().accept_inverted(true);
    let items = [
        (block.surface(), Options::new(), Body::density(2700.0)),
        (inverted.surface(), Options::new(), Body::default()),
        (tetra.surface(), Options::new(), Body::mass(3.0)),
        (inverted.surface(), accepting, Body::default()),
    ];
    let results = polymass::batch(&items).unwrap();
    assert_eq!(results.len(), 4);
    for ((surface, options, body), result) in items.iter().zip(&results) {
        match polymass::mass_properties(surface, options, body) {
            Ok(single) => assert_eq!(result.as_ref().unwrap(), &single),
            Err(error) => {
                let batch_error = result.as_ref().unwrap_err();
                assert_eq!(batch_error.kind(), error.kind());
                assert_eq!(batch_error.to_string(), error.to_string());
            }
        }
    }
    assert_eq!(results[1].as_ref().unwrap_err().kind(), ErrorKind::Inverted);
    assert_eq!(results[3].as_ref().unwrap().warnings, Warnings::INVERTED);
    assert!(polymass::batch(&[]).unwrap().is_empty());
}
