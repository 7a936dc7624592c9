//! Where libnavlink is, and how to link it. A module of build.rs that takes its environment as
//! arguments, so `tests/find_library.rs` runs the same lookup against a pkg-config folder it makes.
//!
//! The order: `NAVLINK_LIB_DIR` (a CMake build tree, or any folder), then pkg-config's `navlink.pc` (an
//! installed NavLink), then a failure that says what to set. There is no silent default: a library
//! found by accident (an old build tree) links, then fails at run time in ways that are hard to trace.
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

/// How the crate links libnavlink.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Linking {
    /// libnavlink.so (the default): the program needs it at run time, next to an rpath or where the
    /// loader looks.
    Shared,
    /// libnavlink.a (`NAVLINK_STATIC=1`), with the C++ runtime and the libraries it needs.
    Static,
}

/// What the lookup found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    pub lib_dir: PathBuf,
    /// Header folders pkg-config named (`Cflags: -I...`); empty when `NAVLINK_LIB_DIR` gave the library.
    pub include_dirs: Vec<PathBuf>,
    /// Libraries a static libnavlink needs after it, in link order (empty for `Linking::Shared`).
    pub static_deps: Vec<String>,
    /// How it was found, for the build's messages: "NAVLINK_LIB_DIR" or "pkg-config".
    pub origin: &'static str,
}

/// What libnavlink.a needs when neither `NAVLINK_STATIC_LIBS` nor navlink.pc says: what `pkg-config
/// --static --libs navlink` lists for a static build (capi/static_library.cmake's `Libs.private` and
/// `Requires.private`): Embree (rays), the Recast builder's Recast and Detour, oneTBB (the core's
/// threads and Embree's), zlib, the loader (plugins), the C++ runtime and libm. In link order: a static
/// link resolves left to right, so each comes before what it needs (embree3 before tbb). glibc 2.34 and
/// later have pthread in libc.
pub const DEFAULT_STATIC_DEPS: [&str; 9] = ["embree3", "Recast", "DetourCrowd", "Detour", "tbb", "z", "dl", "stdc++", "m"];

/// Runs the pkg-config program (`PKG_CONFIG`, else `pkg-config`) with extra environment variables.
pub struct PkgConfig {
    pub program: OsString,
    pub env: Vec<(OsString, OsString)>,
}

impl PkgConfig {
    /// `args` with `navlink` after them; the output's one line, trimmed.
    pub fn query(&self, args: &[&str]) -> Result<String, String> {
        // --print-errors: without it pkg-config says nothing about a missing package in --variable mode.
        let output = Command::new(&self.program)
            .arg("--print-errors")
            .args(args)
            .arg("navlink")
            .envs(self.env.iter().map(|(k, v)| (k, v)))
            .output()
            .map_err(|e| format!("cannot run {}: {} (Debian: apt install pkg-config)", self.program.to_string_lossy(), e))?;
        if !output.status.success() {
            let stderr = String::from_utf8_lossy(&output.stderr);
            let reason = stderr.lines().find(|l| !l.trim().is_empty()).unwrap_or("no navlink.pc found");
            return Err(format!("`{} {} navlink` failed: {}", self.program.to_string_lossy(), args.join(" "), reason.trim()));
        }
        Ok(String::from_utf8_lossy(&output.stdout).trim().to_string())
    }
}

/// The library's file name for `target_os` (cargo's `CARGO_CFG_TARGET_OS`).
pub fn library_file(target_os: &str, linking: Linking) -> &'static str {
    match (target_os, linking) {
        ("windows", _) => "navlink.lib",
        ("macos" | "ios", Linking::Shared) => "libnavlink.dylib",
        (_, Linking::Shared) => "libnavlink.so",
        (_, Linking::Static) => "libnavlink.a",
    }
}

/// Looks for the library in the order of this module's comment. `env` reads the build's environment
/// (`NAVLINK_LIB_DIR`, `NAVLINK_STATIC_LIBS`); `source_build_dir` is the source tree's `build/capi`,
/// named in the failure message when it holds a library.
pub fn find(
    env: &dyn Fn(&str) -> Option<OsString>,
    pkg_config: &PkgConfig,
    target_os: &str,
    linking: Linking,
    source_build_dir: &Path,
) -> Result<Found, String> {
    let file = library_file(target_os, linking);
    let env_static_deps = env("NAVLINK_STATIC_LIBS").map(|libs| libs.to_string_lossy().split_whitespace().map(String::from).collect());
    let static_deps = |from_pc: Option<Vec<String>>| -> Vec<String> {
        match linking {
            Linking::Shared => Vec::new(),
            Linking::Static => env_static_deps
                .clone()
                .or(from_pc.filter(|libs| !libs.is_empty()))
                .unwrap_or_else(|| DEFAULT_STATIC_DEPS.iter().map(|s| s.to_string()).collect()),
        }
    };

    if let Some(dir) = env("NAVLINK_LIB_DIR") {
        let lib_dir = PathBuf::from(dir);
        if !lib_dir.join(file).is_file() {
            return Err(format!(
                "navlink-sys: NAVLINK_LIB_DIR is {}, which holds no {} (a CMake build tree has it in its capi folder)",
                lib_dir.display(),
                file
            ));
        }
        return Ok(Found { lib_dir, include_dirs: Vec::new(), static_deps: static_deps(None), origin: "NAVLINK_LIB_DIR" });
    }

    let pkg_config_error = match pkg_config.query(&["--variable=libdir"]) {
        Ok(lib_dir) if !lib_dir.is_empty() && Path::new(&lib_dir).join(file).is_file() => {
            let include_dirs = pkg_config.query(&["--cflags-only-I"])?;
            let from_pc = match linking {
                Linking::Static => Some(pkg_config.query(&["--static", "--libs-only-l"])?),
                Linking::Shared => None,
            };
            return Ok(Found {
                lib_dir: PathBuf::from(lib_dir),
                include_dirs: include_dirs.split_whitespace().filter_map(|f| f.strip_prefix("-I")).map(PathBuf::from).collect(),
                static_deps: static_deps(from_pc.map(|libs| {
                    libs.split_whitespace().filter_map(|f| f.strip_prefix("-l")).filter(|l| *l != "navlink").map(String::from).collect()
                })),
                origin: "pkg-config",
            });
        }
        Ok(lib_dir) => format!("navlink.pc names libdir {:?}, which holds no {}", lib_dir, file),
        Err(error) => error,
    };
    Err(not_found_message(file, &pkg_config_error, source_build_dir))
}

/// The failure: what was tried, and each way out.
fn not_found_message(file: &str, pkg_config_error: &str, source_build_dir: &Path) -> String {
    let mut message = format!(
        "navlink-sys cannot find {file}.\n\
         - NAVLINK_LIB_DIR is not set.\n\
         - pkg-config: {pkg_config_error}\n\
         Do one of:\n\
         - install NavLink, from its source tree: `cmake --install build --prefix /usr/local` (navlink.pc goes to \
         PREFIX/lib/pkgconfig); for a prefix pkg-config does not search, set PKG_CONFIG_PATH=PREFIX/lib/pkgconfig;\n\
         - set NAVLINK_LIB_DIR to the folder holding {file} (a CMake build's `capi` folder) and NAVLINK_INCLUDE_DIRS \
         to the headers' folders.",
        file = file,
        pkg_config_error = pkg_config_error
    );
    if source_build_dir.join(file).is_file() {
        message.push_str(&format!("\nThis source tree has a build: NAVLINK_LIB_DIR={}", source_build_dir.display()));
    }
    message
}
