//! The committed bindings (src/bindings.rs, used unless the feature
//! `buildtime-bindgen` is on) are what bindgen makes of today's header.
//! Runs with `cargo test -p polymass-sys --features buildtime-bindgen`.
#![cfg(feature = "buildtime-bindgen")]

#[test]
fn committed_bindings_match_a_fresh_bindgen_run() {
    let fresh_path = concat!(env!("OUT_DIR"), "/bindings.rs");
    let fresh = include_str!(concat!(env!("OUT_DIR"), "/bindings.rs"));
    let committed = include_str!("../src/bindings.rs");
    if let Some((line, (ours, theirs))) = committed
        .lines()
        .zip(fresh.lines())
        .enumerate()
        .find(|(_, (ours, theirs))| ours != theirs)
    {
        panic!(
            "src/bindings.rs differs from bindgen's output at line {}:\n  committed: {ours}\n  \
             fresh:     {theirs}\nregenerate it: cp {fresh_path} polymass-sys/src/bindings.rs",
            line + 1
        );
    }
    assert_eq!(
        committed.lines().count(),
        fresh.lines().count(),
        "src/bindings.rs and bindgen's output have different lengths: \
         cp {fresh_path} polymass-sys/src/bindings.rs"
    );
}
