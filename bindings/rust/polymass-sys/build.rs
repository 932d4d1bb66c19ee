//! Finds or builds libpolymass, tells cargo how to link it, and provides the
//! bindings: the committed `src/bindings.rs`, or with the feature
//! `buildtime-bindgen` a fresh bindgen run over the library's own header.
//!
//! Where the library comes from (the first that applies wins):
//! 0. With the feature `bundled`: built here from the C++ sources of the
//!    repository this crate is in, with CMake (the `cmake` crate; Release),
//!    and linked statically. No other source is looked at.
//! 1. `POLYMASS_LIB_DIR`: the directory holding `libpolymass.so` (or
//!    `libpolymass.a` with the `static` feature). The headers are looked up in
//!    `POLYMASS_INCLUDE_DIR` (a `PATH`-style list) if set, otherwise in
//!    `$POLYMASS_LIB_DIR/../include` and this checkout's `include/`, which is
//!    where a CMake build tree (`build/<preset>/src`) and an install prefix keep
//!    them.
//! 2. `pkg-config polymass` (an installed library: `cmake --install`, or the
//!    `libpolymass-dev` package), version 2.0 or a later 2.x (the version of
//!    the header these bindings are written for).
//! 3. The `release` build tree of the checkout this crate lives in
//!    (`build/release/src`, made by `cmake --preset release && cmake --build
//!    --preset release`).
//!
//! Nothing here sets an rpath: cargo's `rustc-link-arg` would only reach this
//! crate's own binaries, not those of the crates that use it, and installed
//! libraries need none. A library outside the loader's search path is found
//! at run time through `LD_LIBRARY_PATH` (scripts/test-rust.sh sets it), or
//! not needed at all with the `static` or `bundled` feature.

// With `bundled`, the search for an installed library (find_library and what it
// calls) is not used.
#![cfg_attr(feature = "bundled", allow(dead_code))]

use std::env;
use std::path::{Path, PathBuf};

#[cfg(feature = "buildtime-bindgen")]
use bindgen::callbacks::{IntKind, ParseCallbacks};

/// Where the library and its headers are.
struct Library {
    /// How it was found, for the messages.
    source: String,
    link_dirs: Vec<PathBuf>,
    include_dirs: Vec<PathBuf>,
}

fn main() {
    println!("cargo:rerun-if-env-changed=POLYMASS_LIB_DIR");
    println!("cargo:rerun-if-env-changed=POLYMASS_INCLUDE_DIR");
    let static_link = cfg!(feature = "bundled") || cfg!(feature = "static");

    #[cfg(feature = "bundled")]
    let library = build_bundled();
    #[cfg(not(feature = "bundled"))]
    let library = find_library(static_link).unwrap_or_else(|reasons| {
        panic!(
            "libpolymass not found:\n{}\n\
                 Build it first (from the repository root: cmake --preset release && \
                 cmake --build --preset release), install it (cmake --install), set \
                 POLYMASS_LIB_DIR to the directory holding {} (and POLYMASS_INCLUDE_DIR to the \
                 directories holding polymass/polymass.h and polymass/polymass_version.h), or \
                 enable the feature `bundled` to build it from source.",
            reasons.join("\n"),
            library_file_name(static_link)
        )
    });
    let header = find_in(&library.include_dirs, "polymass/polymass.h")
        .filter(|_| find_in(&library.include_dirs, "polymass/polymass_version.h").is_some())
        .unwrap_or_else(|| {
            panic!(
                "libpolymass found ({}) but not both polymass/polymass.h and \
                 polymass/polymass_version.h under {:?}: set POLYMASS_INCLUDE_DIR",
                library.source, library.include_dirs
            )
        });

    emit_link_lines(&library, static_link);
    // Crates that compile C against the same library read DEP_POLYMASS_INCLUDE.
    let include_path = env::join_paths(&library.include_dirs).expect("include dirs joinable");
    println!("cargo:include={}", include_path.to_string_lossy());

    check_none_definition(&header);
    #[cfg(feature = "buildtime-bindgen")]
    generate_bindings(&header, &library.include_dirs, static_link);
}

/// Builds libpolymass.a from the repository's sources (feature `bundled`): the
/// library alone, in Release whatever cargo's profile, under OUT_DIR.
#[cfg(feature = "bundled")]
fn build_bundled() -> Library {
    let source = checkout_dir();
    for input in [
        "CMakeLists.txt",
        "cmake",
        "include",
        "src/CMakeLists.txt",
        "src/capi",
        "src/core",
    ] {
        println!("cargo:rerun-if-changed={}", source.join(input).display());
    }
    let out = cmake::Config::new(&source)
        .profile("Release")
        .define("POLYMASS_BUILD_CLI", "OFF")
        .define("POLYMASS_BUILD_TESTS", "OFF")
        .define("POLYMASS_BUILD_EXAMPLES", "OFF")
        .build_target("polymass_static")
        .build();
    let build = out.join("build");
    Library {
        source: format!(
            "bundled: built from {} in {}",
            source.display(),
            build.display()
        ),
        link_dirs: vec![build.join("src")],
        include_dirs: vec![source.join("include"), build.join("include")],
    }
}

fn library_file_name(static_link: bool) -> &'static str {
    if static_link {
        "libpolymass.a"
    } else {
        "libpolymass.so"
    }
}

/// Tries the three sources in order; on failure, why each one did not apply.
fn find_library(static_link: bool) -> Result<Library, Vec<String>> {
    let mut reasons = Vec::new();
    match from_environment(static_link) {
        Ok(Some(library)) => return Ok(library),
        Ok(None) => reasons.push("- POLYMASS_LIB_DIR is not set".to_owned()),
        // A directory the user named explicitly is not silently replaced by another.
        Err(reason) => return Err(vec![reason]),
    }
    match from_pkg_config(static_link) {
        Ok(library) => return Ok(library),
        Err(reason) => reasons.push(format!("- pkg-config: {reason}")),
    }
    match from_build_tree(static_link) {
        Ok(library) => return Ok(library),
        Err(reason) => reasons.push(format!("- build tree: {reason}")),
    }
    Err(reasons)
}

fn from_environment(static_link: bool) -> Result<Option<Library>, String> {
    let Some(lib_dir) = env::var_os("POLYMASS_LIB_DIR").map(PathBuf::from) else {
        return Ok(None);
    };
    if !lib_dir.join(library_file_name(static_link)).is_file() {
        return Err(format!(
            "- POLYMASS_LIB_DIR={} holds no {}",
            lib_dir.display(),
            library_file_name(static_link)
        ));
    }
    let include_dirs = match env::var_os("POLYMASS_INCLUDE_DIR") {
        Some(list) => env::split_paths(&list).collect(),
        None => existing(vec![
            lib_dir.join("../include"),
            checkout_dir().join("include"),
        ]),
    };
    Ok(Some(Library {
        source: format!("POLYMASS_LIB_DIR={}", lib_dir.display()),
        link_dirs: vec![lib_dir],
        include_dirs,
    }))
}

fn from_pkg_config(static_link: bool) -> Result<Library, String> {
    // The link lines are emitted by emit_link_lines, alike for every source.
    let found = pkg_config::Config::new()
        .range_version("2.0".."3")
        .statik(static_link)
        .cargo_metadata(false)
        .env_metadata(true)
        .probe("polymass")
        .map_err(|error| error.to_string().lines().next().unwrap_or("").to_owned())?;
    Ok(Library {
        source: format!("pkg-config polymass {}", found.version),
        link_dirs: found.link_paths,
        include_dirs: found.include_paths,
    })
}

fn from_build_tree(static_link: bool) -> Result<Library, String> {
    let build = checkout_dir().join("build/release");
    let lib_dir = build.join("src");
    let library = lib_dir.join(library_file_name(static_link));
    // Reruns once the library is built, so a failed build retries by itself.
    println!("cargo:rerun-if-changed={}", library.display());
    if !library.is_file() {
        return Err(format!("no {}", library.display()));
    }
    Ok(Library {
        source: format!("build tree {}", build.display()),
        link_dirs: vec![lib_dir],
        include_dirs: vec![checkout_dir().join("include"), build.join("include")],
    })
}

/// The repository root: this crate is bindings/rust/polymass-sys in it.
fn checkout_dir() -> PathBuf {
    let manifest_dir = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("set by cargo"));
    manifest_dir.join("../../..")
}

fn existing(dirs: Vec<PathBuf>) -> Vec<PathBuf> {
    dirs.into_iter().filter(|dir| dir.is_dir()).collect()
}

fn find_in(dirs: &[PathBuf], relative: &str) -> Option<PathBuf> {
    dirs.iter()
        .map(|dir| dir.join(relative))
        .find(|path| path.is_file())
}

fn emit_link_lines(library: &Library, static_link: bool) {
    for dir in &library.link_dirs {
        println!("cargo:rustc-link-search=native={}", dir.display());
    }
    if static_link {
        println!("cargo:rustc-link-lib=static=polymass");
        // The archive is C++ inside: it needs the C++ runtime and libm, as
        // polymass.pc's Libs.private says.
        println!("cargo:rustc-link-lib=dylib=stdc++");
        println!("cargo:rustc-link-lib=dylib=m");
    } else {
        println!("cargo:rustc-link-lib=dylib=polymass");
    }
}

/// POLYMASS_NONE is UINT64_MAX, and bindgen drops integer macros above
/// i64::MAX, so lib.rs defines it as u64::MAX itself; this makes sure the
/// header still says so.
fn check_none_definition(header: &Path) {
    let text = std::fs::read_to_string(header)
        .unwrap_or_else(|error| panic!("cannot read {}: {error}", header.display()));
    let defined_as_max = text.lines().any(|line| {
        let words: Vec<&str> = line.split_whitespace().collect();
        words == ["#define", "POLYMASS_NONE", "UINT64_MAX"]
    });
    assert!(
        defined_as_max,
        "{} no longer defines POLYMASS_NONE as UINT64_MAX: update POLYMASS_NONE in polymass-sys/src/lib.rs",
        header.display()
    );
}

/// Gives each POLYMASS_* constant the type of the C field or return value it
/// is compared with, so Rust code needs no casts: statuses, orientations and
/// shell kinds are int32_t, everything else (flags,
/// warnings, type and mode codes, version numbers) is uint32_t.
#[cfg(feature = "buildtime-bindgen")]
#[derive(Debug)]
struct ConstantTypes;

#[cfg(feature = "buildtime-bindgen")]
impl ParseCallbacks for ConstantTypes {
    fn int_macro(&self, name: &str, _value: i64) -> Option<IntKind> {
        let kind = if name == "POLYMASS_OK"
            || name.starts_with("POLYMASS_ERROR_")
            || name.starts_with("POLYMASS_SHELL_")
            || name.ends_with("CLOCKWISE")
        {
            IntKind::I32
        } else {
            IntKind::U32
        };
        Some(kind)
    }
}

/// Writes OUT_DIR/bindings.rs, which lib.rs includes instead of the committed
/// src/bindings.rs (tests/bindings_up_to_date.rs compares the two).
#[cfg(feature = "buildtime-bindgen")]
fn generate_bindings(header: &Path, include_dirs: &[PathBuf], static_link: bool) {
    use std::ffi::OsString;

    let mut clang_args: Vec<OsString> = include_dirs
        .iter()
        .map(|dir| {
            let mut arg = OsString::from("-I");
            arg.push(dir);
            arg
        })
        .collect();
    if static_link {
        clang_args.push("-DPOLYMASS_STATIC".into());
    }
    let out_dir = PathBuf::from(env::var_os("OUT_DIR").expect("set by cargo"));
    let bindings = bindgen::Builder::default()
        .header(header.to_string_lossy())
        .clang_args(
            clang_args
                .iter()
                .map(|arg| arg.to_string_lossy().into_owned()),
        )
        .allowlist_function("polymass_.*")
        .allowlist_type("polymass_.*")
        .allowlist_var("POLYMASS_.*")
        // The header has no C enums; should one appear, its values become
        // constants: a value the Rust side does not know would otherwise be
        // undefined behaviour.
        .default_enum_style(bindgen::EnumVariation::Consts)
        .parse_callbacks(Box::new(ConstantTypes))
        .parse_callbacks(Box::new(bindgen::CargoCallbacks::new()))
        .derive_default(true)
        .derive_debug(true)
        .layout_tests(true)
        .generate()
        .expect("bindgen could not translate polymass.h");
    let out = out_dir.join("bindings.rs");
    bindings
        .write_to_file(&out)
        .unwrap_or_else(|error| panic!("cannot write {}: {error}", out.display()));
}
