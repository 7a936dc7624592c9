//! Whether a program linked against libnavlink.so now would find it when it starts. A module of build.rs
//! that takes its environment as arguments (the variable lookup, `ldconfig -p`'s output, the encoded
//! rustflags), so `tests/run_path.rs` runs the decision as a function.
//!
//! Why the build checks it: an rpath navlink-sys passes (`cargo:rustc-link-arg`) reaches only navlink-sys's
//! own targets, and cargo has no way to pass a link argument to the crates that depend on it. A program
//! built from a crate that depends on `navlink` linked fine and then exited 127 (libnavlink.so.0 not
//! found). So the build fails instead, unless one of these holds:
//! - the folder is one the loader searches by default (`/lib`, `/usr/lib`, `/lib64`, `/usr/lib64` and
//!   their Debian multiarch folders, such as `/usr/lib/x86_64-linux-gnu`);
//! - the loader's cache lists the library in that folder (`ldconfig -p`: an `/etc/ld.so.conf.d` entry
//!   and `ldconfig`, as after `cmake --install` to `/usr/local`);
//! - the build's rustflags (`CARGO_ENCODED_RUSTFLAGS`, every source of rustflags: `RUSTFLAGS`,
//!   `[target.<triple>] rustflags` in `.cargo/config.toml`, `CARGO_TARGET_<TRIPLE>_RUSTFLAGS`, `--config`)
//!   put the folder on the run path (`-C link-arg=-Wl,-rpath,DIR`): they reach every binary cargo links;
//! - `NAVLINK_RUN_PATH=loader`: the user puts the folder on the loader's path themselves
//!   (`LD_LIBRARY_PATH` when the program runs, an `/etc/ld.so.conf.d` entry).
//!
//! For ELF targets only (the library a `libnavlink.so`): elsewhere build.rs does not ask.
use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The variable that says "I put the folder on the loader's path myself", and its one value.
pub const OPT_OUT: &str = "NAVLINK_RUN_PATH";
pub const OPT_OUT_VALUE: &str = "loader";

/// Why a program will find the library.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reach {
    /// The folder is one the loader searches by default.
    DefaultFolder,
    /// `ldconfig -p` lists the library in the folder.
    LoaderCache,
    /// The rustflags put the folder on the run path.
    Rustflags,
    /// `NAVLINK_RUN_PATH=loader`.
    SaidByUser,
}

/// Decides for the library in `lib_dir`, found through `origin` ("NAVLINK_LIB_DIR" or "pkg-config"),
/// for the target triple `target` (cargo's `TARGET`). `env` reads `NAVLINK_RUN_PATH`; `ldconfig` is the
/// output of `ldconfig -p` (empty when it could not run); `encoded_rustflags` is `CARGO_ENCODED_RUSTFLAGS`.
pub fn check(
    lib_dir: &Path,
    origin: &str,
    target: &str,
    env: &dyn Fn(&str) -> Option<OsString>,
    ldconfig: &str,
    encoded_rustflags: &str,
) -> Result<Reach, String> {
    match env(OPT_OUT).filter(|v| !v.is_empty()) {
        Some(value) if value == OPT_OUT_VALUE => return Ok(Reach::SaidByUser),
        Some(value) => {
            return Err(format!(
                "navlink-sys: {} is {:?}; the one value it takes is `{}` (you put {} on the loader's path yourself)",
                OPT_OUT,
                value,
                OPT_OUT_VALUE,
                lib_dir.display()
            ))
        }
        None => {}
    }
    if default_folders(target).iter().any(|d| same_folder(d, lib_dir)) {
        return Ok(Reach::DefaultFolder);
    }
    if cached_folders(ldconfig).iter().any(|d| same_folder(d, lib_dir)) {
        return Ok(Reach::LoaderCache);
    }
    if rpath_folders(encoded_rustflags).iter().any(|d| same_folder(d, lib_dir)) {
        return Ok(Reach::Rustflags);
    }
    Err(unreachable_message(lib_dir, origin, target))
}

/// The folders the loader searches without being told: glibc's built-in ones and, on Debian and its
/// derivatives, the multiarch folders of `target` (which the loader's cache holds).
pub fn default_folders(target: &str) -> Vec<PathBuf> {
    let mut folders: Vec<PathBuf> = ["/lib", "/usr/lib", "/lib64", "/usr/lib64"].iter().map(PathBuf::from).collect();
    if let Some(tuple) = multiarch(target) {
        folders.push(Path::new("/lib").join(&tuple));
        folders.push(Path::new("/usr/lib").join(&tuple));
    }
    folders
}

/// Debian's multiarch tuple for a Rust target triple: `x86_64-unknown-linux-gnu` -> `x86_64-linux-gnu`,
/// `i686-unknown-linux-gnu` -> `i386-linux-gnu`, `armv7-unknown-linux-gnueabihf` -> `arm-linux-gnueabihf`.
pub fn multiarch(target: &str) -> Option<String> {
    let parts: Vec<&str> = target.split('-').collect();
    let (arch, os, abi) = match parts.as_slice() {
        [arch, _vendor, os, abi] => (*arch, *os, *abi),
        [arch, os, abi] => (*arch, *os, *abi),
        _ => return None,
    };
    if os != "linux" {
        return None;
    }
    let arch = match arch {
        "i386" | "i586" | "i686" => "i386",
        a if a.starts_with("armv") || a == "arm" => "arm",
        a => a,
    };
    Some(format!("{}-linux-{}", arch, abi))
}

/// The folders where `ldconfig -p` lists a versioned libnavlink (`libnavlink.so.0 (libc6,x86-64) =>
/// /usr/local/lib/libnavlink.so.0`). Versioned only: the loader looks a library up by its SONAME.
pub fn cached_folders(ldconfig: &str) -> Vec<PathBuf> {
    ldconfig
        .lines()
        .filter_map(|line| line.trim().split_once(" => "))
        .filter(|(entry, _)| entry.split_whitespace().next().map_or(false, |name| name.starts_with("libnavlink.so.")))
        .filter_map(|(_, path)| Path::new(path.trim()).parent().map(Path::to_path_buf))
        .collect()
}

/// The folders `encoded_rustflags` (separated by 0x1f) put on the run path: `-C link-arg=-Wl,-rpath,DIR`,
/// `-Clink-arg=-Wl,-rpath=DIR`, `-C link-args=...`, with several folders separated by `:`.
pub fn rpath_folders(encoded_rustflags: &str) -> Vec<PathBuf> {
    let flags: Vec<&str> = encoded_rustflags.split('\x1f').filter(|f| !f.is_empty()).collect();
    // What the rustflags hand the C compiler that links.
    let mut compiler_args: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < flags.len() {
        let option = match flags[i] {
            "-C" | "--codegen" => {
                i += 1;
                flags.get(i).copied()
            }
            flag => flag.strip_prefix("-C").or_else(|| flag.strip_prefix("--codegen=")).or(Some(flag)),
        };
        if let Some(option) = option {
            if let Some(arg) = option.strip_prefix("link-arg=") {
                compiler_args.push(arg);
            } else if let Some(args) = option.strip_prefix("link-args=") {
                compiler_args.extend(args.split_whitespace());
            } else if option.starts_with("-Wl,") {
                compiler_args.push(option);
            }
        }
        i += 1;
    }
    // What the compiler hands the linker: `-Wl,a,b` gives a and b.
    let linker_args: Vec<&str> = compiler_args
        .iter()
        .flat_map(|arg| arg.strip_prefix("-Wl,").map_or_else(|| vec![*arg], |rest| rest.split(',').collect()))
        .collect();
    let mut folders = Vec::new();
    let mut args = linker_args.iter();
    while let Some(arg) = args.next() {
        let value = match *arg {
            "-rpath" | "--rpath" => args.next().copied(),
            arg => arg.strip_prefix("-rpath=").or_else(|| arg.strip_prefix("--rpath=")),
        };
        if let Some(value) = value {
            folders.extend(value.split(':').filter(|d| !d.is_empty()).map(PathBuf::from));
        }
    }
    folders
}

/// The loader's cache, as `ldconfig -p` prints it; empty when no ldconfig runs (sbin is often off a
/// user's PATH, so its usual places are tried too).
pub fn loader_cache() -> String {
    for program in ["ldconfig", "/sbin/ldconfig", "/usr/sbin/ldconfig"] {
        if let Ok(output) = Command::new(program).arg("-p").output() {
            if output.status.success() {
                return String::from_utf8_lossy(&output.stdout).into_owned();
            }
        }
    }
    String::new()
}

/// The same folder, after symbolic links (`/lib` is `/usr/lib` on a merged-/usr system).
fn same_folder(a: &Path, b: &Path) -> bool {
    let resolve = |p: &Path| fs::canonicalize(p).unwrap_or_else(|_| p.components().collect());
    resolve(a) == resolve(b)
}

/// The name the program asks the loader for: the shortest `libnavlink.so.N...` in the folder (the
/// SONAME link a CMake build or install makes), else `libnavlink.so.0`.
fn soname(lib_dir: &Path) -> String {
    let mut names: Vec<String> = fs::read_dir(lib_dir)
        .map(|entries| entries.filter_map(|e| e.ok()).map(|e| e.file_name().to_string_lossy().into_owned()).collect())
        .unwrap_or_default();
    names.retain(|n| n.starts_with("libnavlink.so."));
    names.sort_by_key(|n| n.len());
    names.into_iter().next().unwrap_or_else(|| "libnavlink.so.0".to_string())
}

/// The failure: where the library is, why a program would not start, and each way out.
fn unreachable_message(lib_dir: &Path, origin: &str, target: &str) -> String {
    let how = match origin {
        "pkg-config" => "pkg-config's navlink.pc (its libdir)".to_string(),
        other => other.to_string(),
    };
    let dir = lib_dir.display();
    let link_arg = format!("link-arg=-Wl,-rpath,{}", dir);
    format!(
        "navlink-sys found {soname} in {dir} (through {how}), but a program built now would not start: nothing \
         tells the loader to look there, so it would exit with \"{soname}: cannot open shared object file\". \
         That folder is not one the loader searches by default, `ldconfig -p` does not list the library there, \
         and this build's rustflags put no -rpath to it. (navlink-sys cannot add the rpath for you: cargo passes \
         a crate's link arguments to none of the crates that depend on it.)\n\
         Do one of:\n\
         - put the folder on the run path of what cargo links: add to .cargo/config.toml (in your project, or \
         $CARGO_HOME/config.toml):\n\
         \n\
         [target.{target}]\n\
         rustflags = [\"-C\", {link_arg:?}]\n\
         \n\
         \x20 (for one build: CARGO_TARGET_{target_var}_RUSTFLAGS=\"-C {link_arg}\"; a RUSTFLAGS variable, when set, \
         replaces the config's rustflags, so add it there instead);\n\
         - link statically: install NavLink built with -DNAVLINK_SHARED=OFF (libnavlink.a) and set NAVLINK_STATIC=1;\n\
         - if you put the folder on the loader's path yourself (LD_LIBRARY_PATH where the program runs, or an \
         /etc/ld.so.conf.d entry and ldconfig), set {opt_out}={opt_out_value}.",
        soname = soname(lib_dir),
        dir = dir,
        how = how,
        target = target,
        link_arg = link_arg,
        target_var = target.to_uppercase().replace(['-', '.'], "_"),
        opt_out = OPT_OUT,
        opt_out_value = OPT_OUT_VALUE,
    )
}
