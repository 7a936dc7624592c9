//! Finds and links libnavlink, checks that a program linked against it will find it at run time, and
//! writes the C compiler's view of the headers' structs and constants for `tests/layout.rs`.
//!
//! Where the library is (build/find_library.rs), in this order:
//! 1. `NAVLINK_LIB_DIR`: the folder holding libnavlink.so (a CMake build's `capi` folder).
//! 2. pkg-config's `navlink.pc` (an installed NavLink; `PKG_CONFIG_PATH` for a prefix pkg-config does not
//!    search): its `libdir`, and its `-I` folders for the headers.
//! 3. Otherwise the build fails, saying what to set.
//!
//! The folder goes on the link search path. Whether a program will find libnavlink.so.0 when it starts
//! (build/run_path.rs): an rpath passed from here would reach only this package's own targets (cargo passes
//! no link argument to dependents), so the build checks instead that the folder is one the loader searches
//! (a default folder, or listed by `ldconfig -p`) or that the build's rustflags carry
//! `-C link-arg=-Wl,-rpath,DIR` for it; otherwise it fails with the `.cargo/config.toml` lines to add
//! (docs/bindings.md, Rust). The folder is also given to dependents as `DEP_NAVLINK_LIB_DIR`
//! (`links = "navlink"`).
//!
//! Other environment (each optional):
//! - `NAVLINK_RUN_PATH=loader`: skip that check: you put the folder on the loader's path yourself
//!   (`LD_LIBRARY_PATH` where the program runs, an `/etc/ld.so.conf.d` entry and `ldconfig`).
//! - `NAVLINK_STATIC=1`: link libnavlink.a instead, followed by `NAVLINK_STATIC_LIBS` (space-separated
//!   library names), else what `pkg-config --static` lists for navlink.pc, else `embree3 Recast
//!   DetourCrowd Detour tbb z dl stdc++ m`. Nothing to find at run time then, so no check.
//! - `NAVLINK_INCLUDE_DIRS`: folders holding `navlink/navlink.h`, `recast.h`, `plugin.h` and the generated
//!   `version.h`, separated as PATH is (default: pkg-config's; with NAVLINK_LIB_DIR, the source tree's
//!   `capi/include` and `$NAVLINK_LIB_DIR/include`).
//! - `CC`: the C compiler for the layout probe (default `cc`).
use std::env;
use std::fs;
use std::path::{Path, PathBuf};

#[path = "build/find_library.rs"]
mod find_library;
#[path = "build/layout_probe.rs"]
mod layout_probe;
#[path = "build/run_path.rs"]
mod run_path;

use find_library::{Linking, PkgConfig};

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let source_root = manifest.join("../../..");
    for var in [
        "NAVLINK_LIB_DIR",
        "NAVLINK_INCLUDE_DIRS",
        "NAVLINK_STATIC",
        "NAVLINK_STATIC_LIBS",
        // (No line for the rustflags: cargo runs this again when they change, --target or not.)
        run_path::OPT_OUT,
        "PKG_CONFIG",
        "PKG_CONFIG_PATH",
        "PKG_CONFIG_LIBDIR",
        "PKG_CONFIG_SYSROOT_DIR",
        "CC",
    ] {
        println!("cargo:rerun-if-env-changed={}", var);
    }
    println!("cargo:rerun-if-changed=build");

    let linking = if env::var_os("NAVLINK_STATIC").map_or(false, |v| v == "1") { Linking::Static } else { Linking::Shared };
    let pkg_config = PkgConfig { program: env::var_os("PKG_CONFIG").unwrap_or_else(|| "pkg-config".into()), env: Vec::new() };
    let target_os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let source_build_dir = fs::canonicalize(source_root.join("build/capi")).unwrap_or_else(|_| source_root.join("build/capi"));
    let found =
        find_library::find(&|name| env::var_os(name), &pkg_config, &target_os, linking, &source_build_dir).unwrap_or_else(|m| fail(&m));
    let lib_dir = fs::canonicalize(&found.lib_dir).unwrap_or_else(|_| found.lib_dir.clone());
    println!("cargo:rustc-link-search=native={}", lib_dir.display());
    match linking {
        Linking::Shared => {
            println!("cargo:rustc-link-lib=dylib=navlink");
            // An ELF shared library: the loader must find it when a program starts (build/run_path.rs).
            if find_library::library_file(&target_os, linking) == "libnavlink.so" {
                let target = env::var("TARGET").unwrap_or_default();
                let rustflags = env::var("CARGO_ENCODED_RUSTFLAGS").unwrap_or_default();
                run_path::check(&lib_dir, found.origin, &target, &|name| env::var_os(name), &run_path::loader_cache(), &rustflags)
                    .unwrap_or_else(|m| fail(&m));
            }
            // Only a shared library is needed at run time, so only then do dependents get its folder.
            println!("cargo:lib_dir={}", lib_dir.display());
        }
        Linking::Static => {
            println!("cargo:rustc-link-lib=static=navlink");
            for dep in &found.static_deps {
                println!("cargo:rustc-link-lib=dylib={}", dep);
            }
        }
    }

    let include_dirs: Vec<PathBuf> = match env::var_os("NAVLINK_INCLUDE_DIRS") {
        Some(dirs) => env::split_paths(&dirs).collect(),
        None if !found.include_dirs.is_empty() => found.include_dirs.clone(),
        None => vec![source_root.join("capi/include"), lib_dir.join("include")],
    };
    let out_dir = PathBuf::from(env::var("OUT_DIR").unwrap());
    write_layout(&include_dirs, &out_dir);
}

/// Ends the build with `message`: cargo prints a failed build script's stderr, so it is the whole explanation.
fn fail(message: &str) -> ! {
    eprintln!("{}", message);
    std::process::exit(1);
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
