//! The structs bindgen generated have the sizes the loaded library was
//! compiled with, and the library has the header's major version: a mismatch
//! here means the bindings and the library disagree about memory layout.

use polymass_sys as sys;
use std::ffi::CStr;
use std::mem::size_of;

fn size_of_u32<T>() -> u32 {
    u32::try_from(size_of::<T>()).expect("struct sizes fit in u32")
}

#[test]
fn struct_sizes_match_the_library() {
    let sizes = unsafe {
        [
            (
                "polymass_allocator",
                size_of_u32::<sys::polymass_allocator>(),
                sys::polymass_sizeof_allocator(),
            ),
            (
                "polymass_options",
                size_of_u32::<sys::polymass_options>(),
                sys::polymass_sizeof_options(),
            ),
            (
                "polymass_mesh_desc",
                size_of_u32::<sys::polymass_mesh_desc>(),
                sys::polymass_sizeof_mesh_desc(),
            ),
            (
                "polymass_mass_desc",
                size_of_u32::<sys::polymass_mass_desc>(),
                sys::polymass_sizeof_mass_desc(),
            ),
            (
                "polymass_moments",
                size_of_u32::<sys::polymass_moments>(),
                sys::polymass_sizeof_moments(),
            ),
            (
                "polymass_mass_properties",
                size_of_u32::<sys::polymass_mass_properties>(),
                sys::polymass_sizeof_mass_properties(),
            ),
            (
                "polymass_diagnostics",
                size_of_u32::<sys::polymass_diagnostics>(),
                sys::polymass_sizeof_diagnostics(),
            ),
            (
                "polymass_polygon_properties",
                size_of_u32::<sys::polymass_polygon_properties>(),
                sys::polymass_sizeof_polygon_properties(),
            ),
            (
                "polymass_shell",
                size_of_u32::<sys::polymass_shell>(),
                sys::polymass_sizeof_shell(),
            ),
            (
                "polymass_provenance",
                size_of_u32::<sys::polymass_provenance>(),
                sys::polymass_sizeof_provenance(),
            ),
            (
                "polymass_batch_item",
                size_of_u32::<sys::polymass_batch_item>(),
                sys::polymass_sizeof_batch_item(),
            ),
        ]
    };
    for (name, rust, library) in sizes {
        assert_eq!(
            rust, library,
            "size of {name}: Rust {rust}, library {library}"
        );
    }
}

#[test]
fn library_major_version_matches_the_header() {
    let number = unsafe { sys::polymass_version() };
    assert_eq!(number / 10000, sys::POLYMASS_VERSION_MAJOR);
    let text = unsafe { CStr::from_ptr(sys::polymass_version_string()) };
    let expected = format!("{}.{}.{}", number / 10000, number / 100 % 100, number % 100);
    assert_eq!(text.to_str().unwrap(), expected);
}

#[test]
fn every_status_has_a_name_and_unknown_codes_say_so() {
    let name = |status: i32| unsafe { CStr::from_ptr(sys::polymass_status_string(status)) };
    let unknown = name(-12345);
    assert_eq!(unknown.to_str().unwrap(), "unknown status");
    for status in [
        sys::POLYMASS_OK,
        sys::POLYMASS_ERROR_INVALID_ARGUMENT,
        sys::POLYMASS_ERROR_OUT_OF_MEMORY,
        sys::POLYMASS_ERROR_INTERNAL,
        sys::POLYMASS_ERROR_NON_FINITE,
        sys::POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
        sys::POLYMASS_ERROR_FACE_TOO_SMALL,
        sys::POLYMASS_ERROR_OPEN,
        sys::POLYMASS_ERROR_NON_MANIFOLD,
        sys::POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
        sys::POLYMASS_ERROR_NON_PLANAR_FACE,
        sys::POLYMASS_ERROR_INTERSECTING,
        sys::POLYMASS_ERROR_INVERTED,
        sys::POLYMASS_ERROR_ZERO_VOLUME,
        sys::POLYMASS_ERROR_ZERO_AREA,
        sys::POLYMASS_ERROR_OVERFLOW,
    ] {
        assert_ne!(name(status), unknown, "status {status} has no name");
    }
}
