//! Area properties of 2D polygons against closed forms, in both
//! orientations and far from the origin.

mod common;

use common::{assert_close, TOLERANCE};
use polymass::{Orientation, SecondMoments};

/// A w x h rectangle with its lower-left corner at (x, y), counter-clockwise.
fn rectangle(x: f64, y: f64, w: f64, h: f64) -> Vec<[f64; 2]> {
    vec![[x, y], [x + w, y], [x + w, y + h], [x, y + h]]
}

fn assert_moments(actual: &SecondMoments, expected: &SecondMoments, scale: f64, what: &str) {
    for (name, a, e) in [
        ("ixx", actual.ixx, expected.ixx),
        ("iyy", actual.iyy, expected.iyy),
        ("ixy", actual.ixy, expected.ixy),
    ] {
        assert!(
            (a - e).abs() <= TOLERANCE * scale,
            "{what} {name}: {a:e}, expected {e:e}"
        );
    }
}

#[test]
fn rectangle_in_both_orientations() {
    let (x, y, w, h) = (1.0, -2.0, 3.0, 0.5);
    let ccw = rectangle(x, y, w, h);
    let cw: Vec<[f64; 2]> = ccw.iter().rev().copied().collect();
    for (points, orientation) in [
        (ccw, Orientation::CounterClockwise),
        (cw, Orientation::Clockwise),
    ] {
        let p = polymass::polygon(&points).unwrap();
        assert_eq!(p.orientation, orientation);
        let area = w * h;
        assert_close(p.area, area, "area");
        assert_eq!(p.centroid, [x + w / 2.0, y + h / 2.0]);
        let about_centroid = SecondMoments {
            ixx: area * h * h / 12.0,
            iyy: area * w * w / 12.0,
            ixy: 0.0,
        };
        assert_moments(
            &p.second_moments,
            &about_centroid,
            about_centroid.iyy,
            "centroid",
        );
        let [cx, cy] = p.centroid;
        let about_origin = SecondMoments {
            ixx: about_centroid.ixx + area * cy * cy,
            iyy: about_centroid.iyy + area * cx * cx,
            ixy: area * cx * cy,
        };
        assert_moments(
            &p.second_moments_origin,
            &about_origin,
            about_origin.iyy,
            "origin",
        );
        assert_close(
            p.polar_moment,
            about_centroid.ixx + about_centroid.iyy,
            "polar",
        );
        assert_eq!(
            p.principal_moments,
            [about_centroid.ixx, about_centroid.iyy]
        );
        // The smaller moment is about the long side, along x.
        assert!(p.principal_angle.abs() <= TOLERANCE);
    }
}

#[test]
fn right_triangle_has_the_textbook_product_of_area() {
    let (a, b) = (3.0, 2.0);
    let p = polymass::polygon(&[[0.0, 0.0], [a, 0.0], [0.0, b]]).unwrap();
    assert_close(p.area, a * b / 2.0, "area");
    let expected = SecondMoments {
        ixx: a * b * b * b / 36.0,
        iyy: a * a * a * b / 36.0,
        ixy: -a * a * b * b / 72.0,
    };
    assert_moments(&p.second_moments, &expected, expected.iyy, "triangle");
}

#[test]
fn non_convex_l_shape_is_two_rectangles() {
    let l = [
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ];
    let p = polymass::polygon(&l).unwrap();
    // Foot [0,4]x[0,1] (area 4, centroid (2, 0.5)) and leg [0,1]x[1,3]
    // (area 2, centroid (0.5, 2)).
    assert_close(p.area, 6.0, "area");
    assert_close(p.centroid[0], (4.0 * 2.0 + 2.0 * 0.5) / 6.0, "centroid x");
    assert_close(p.centroid[1], (4.0 * 0.5 + 2.0 * 2.0) / 6.0, "centroid y");
    let origin = SecondMoments {
        ixx: 4.0 / 3.0 + (27.0 - 1.0) / 3.0, // ∫y²: foot 4·1/3, leg 1·∫₁³y² dy
        iyy: 64.0 / 3.0 + 2.0 / 3.0,         // ∫x²: foot ∫₀⁴x² dx, leg 2·1/3
        ixy: 4.0 * 2.0 * 0.5 + 2.0 * 0.5 * 2.0, // area · cx · cy of each
    };
    assert_moments(
        &p.second_moments_origin,
        &origin,
        origin.iyy,
        "L about origin",
    );
}

#[test]
fn far_from_the_origin_the_centroid_moments_keep_their_digits() {
    for offset in [1e6, 1e8] {
        let p = polymass::polygon(&rectangle(offset, -offset, 2.0, 1.0)).unwrap();
        assert_close(p.area, 2.0, "area");
        let expected = SecondMoments {
            ixx: 2.0 / 12.0,
            iyy: 8.0 / 12.0,
            ixy: 0.0,
        };
        assert_moments(&p.second_moments, &expected, expected.iyy, "far rectangle");
    }
}

#[test]
fn rotated_rectangle_reports_its_principal_angle() {
    let angle: f64 = 0.5;
    let (s, c) = angle.sin_cos();
    let points: Vec<[f64; 2]> = rectangle(-2.0, -0.5, 4.0, 1.0)
        .iter()
        .map(|&[x, y]| [c * x - s * y, s * x + c * y])
        .collect();
    let p = polymass::polygon(&points).unwrap();
    // The smaller moment (4·1³/12) is about the long side, turned by `angle`.
    assert_close(p.principal_moments[0], 4.0 / 12.0, "smaller moment");
    assert_close(p.principal_moments[1], 64.0 / 12.0, "larger moment");
    assert!(
        (p.principal_angle - angle).abs() <= 1e-12,
        "angle {}",
        p.principal_angle
    );
}
