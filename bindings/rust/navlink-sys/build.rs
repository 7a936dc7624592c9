//! Links libnavlink.so from the CMake build, and writes the C compiler's view of the headers' structs and
//! constants for `tests/layout.rs`.
//!
//! Environment (each optional):
//! - `NAVLINK_LIB_DIR`: folder holding libnavlink.so (default: `build/capi` of this source tree). Added to
//!   the link search path and, as an rpath, to this package's test binaries; dependents get it as
//!   `DEP_NAVLINK_LIB_DIR` (the `navlink` crate adds the rpath to its own).
//! - `NAVLINK_INCLUDE_DIRS`: folders holding `navlink/navlink.h`, `recast.h`, `plugin.h` and the generated
//!   `version.h`, separated as PATH is (default: the source tree's `capi/include` and `plugins/include`, and
//!   `$NAVLINK_LIB_DIR/include`; for an installed NavLink, `PREFIX/include` alone).
//! - `CC`: the C compiler for the layout probe (default `cc`).
use std::env;
use std::fs;
use std::path::{Path, PathBuf};

#[path = "build/layout_probe.rs"]
mod layout_probe;

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let source_root = manifest.join("../../..");
    for var in ["NAVLINK_LIB_DIR", "NAVLINK_INCLUDE_DIRS", "CC"] {
        println!("cargo:rerun-if-env-changed={}", var);
    }
    println!("cargo:rerun-if-changed=build");

    let lib_dir = env::var_os("NAVLINK_LIB_DIR").map(PathBuf::from).unwrap_or_else(|| source_root.join("build/capi"));
    let lib_dir = fs::canonicalize(&lib_dir).unwrap_or(lib_dir);
    if !lib_dir.join("libnavlink.so").exists() {
        println!("cargo:warning=no libnavlink.so in {} (set NAVLINK_LIB_DIR to the CMake build's capi folder)", lib_dir.display());
    }
    println!("cargo:rustc-link-search=native={}", lib_dir.display());
    println!("cargo:rustc-link-lib=dylib=navlink");
    // So this package's tests find the library without LD_LIBRARY_PATH.
    println!("cargo:rustc-link-arg=-Wl,-rpath,{}", lib_dir.display());
    println!("cargo:lib_dir={}", lib_dir.display());

    let include_dirs: Vec<PathBuf> = match env::var_os("NAVLINK_INCLUDE_DIRS") {
        Some(dirs) => env::split_paths(&dirs).collect(),
        None => vec![source_root.join("capi/include"), source_root.join("plugins/include"), lib_dir.join("include")],
    };
    let out_dir = PathBuf::from(env::var("OUT_DIR").unwrap());
    write_layout(&include_dirs, &out_dir);
}

/// Writes `$OUT_DIR/c_layout.rs`. If the probe cannot be built (no headers, no C compiler), a library
/// user's build still succeeds, but the file holds a compile_error!, so the layout test fails, never skips.
fn write_layout(include_dirs: &[PathBuf], out_dir: &Path) {
    let target = out_dir.join("c_layout.rs");
    let compiler = env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let text = match layout_probe::run(include_dirs, out_dir, &compiler) {
        Ok(rust) => rust,
        Err(reason) => {
            println!("cargo:warning=navlink-sys: no C layout probe ({}); tests/layout.rs will fail", reason);
            format!("compile_error!({:?});\n", format!("navlink-sys build.rs could not probe the C layout: {}", reason))
        }
    };
    fs::write(&target, text).expect("write c_layout.rs");
    for dir in include_dirs {
        println!("cargo:rerun-if-changed={}", dir.join("navlink").display());
    }
}
