//! build.rs's run-time check (build/run_path.rs), run as a function: the environment, `ldconfig -p`'s
//! output and the encoded rustflags are what each test writes.
#[path = "../build/run_path.rs"]
#[allow(dead_code)]
mod run_path;

use run_path::{cached_folders, check, default_folders, multiarch, rpath_folders, Reach};
use std::ffi::OsString;
use std::path::{Path, PathBuf};

const TARGET: &str = "x86_64-unknown-linux-gnu";
/// A folder no loader searches (it need not exist: folders that do not are compared as written).
const PREFIX_LIB: &str = "/opt/navlink-test-prefix/lib";

fn no_env(_: &str) -> Option<OsString> {
    None
}

fn env_with(value: &'static str) -> impl Fn(&str) -> Option<OsString> {
    move |name| if name == run_path::OPT_OUT { Some(value.into()) } else { None }
}

/// Rustflags as cargo encodes them for a build script: separated by 0x1f.
fn encoded(flags: &[&str]) -> String {
    flags.join("\x1f")
}

#[test]
fn a_folder_of_ones_own_is_refused_with_what_to_do() {
    let error = check(Path::new(PREFIX_LIB), "pkg-config", TARGET, &no_env, "", "").unwrap_err();
    for needed in [
        PREFIX_LIB,
        "navlink.pc",
        "would not start",
        "[target.x86_64-unknown-linux-gnu]\nrustflags = [\"-C\", \"link-arg=-Wl,-rpath,/opt/navlink-test-prefix/lib\"]\n",
        "CARGO_TARGET_X86_64_UNKNOWN_LINUX_GNU_RUSTFLAGS",
        "NAVLINK_STATIC=1",
        "NAVLINK_RUN_PATH=loader",
        "LD_LIBRARY_PATH",
    ] {
        assert!(error.contains(needed), "no {:?} in:\n{}", needed, error);
    }
    let error = check(Path::new(PREFIX_LIB), "NAVLINK_LIB_DIR", TARGET, &no_env, "", "").unwrap_err();
    assert!(error.contains("through NAVLINK_LIB_DIR"), "{}", error);
}

#[test]
fn the_loaders_default_folders_need_nothing() {
    for folder in ["/usr/lib", "/lib64", "/usr/lib/x86_64-linux-gnu", "/lib/x86_64-linux-gnu/"] {
        assert_eq!(check(Path::new(folder), "pkg-config", TARGET, &no_env, "", ""), Ok(Reach::DefaultFolder), "{}", folder);
    }
    // /usr/local/lib is searched only through the cache (ld.so.conf), not by default.
    assert!(check(Path::new("/usr/local/lib"), "pkg-config", TARGET, &no_env, "", "").is_err());
    assert_eq!(multiarch("i686-unknown-linux-gnu").as_deref(), Some("i386-linux-gnu"));
    assert_eq!(multiarch("armv7-unknown-linux-gnueabihf").as_deref(), Some("arm-linux-gnueabihf"));
    assert_eq!(multiarch("aarch64-unknown-linux-gnu").as_deref(), Some("aarch64-linux-gnu"));
    assert_eq!(multiarch("x86_64-apple-darwin"), None);
    assert!(default_folders("aarch64-unknown-linux-gnu").contains(&PathBuf::from("/usr/lib/aarch64-linux-gnu")));
}

#[test]
fn the_loaders_cache_counts_when_it_lists_the_library_in_that_folder() {
    let cache = "1234 libs found in cache `/etc/ld.so.cache'\n\
                 \tlibz.so.1 (libc6,x86-64) => /lib/x86_64-linux-gnu/libz.so.1\n\
                 \tlibnavlink.so.0 (libc6,x86-64) => /opt/navlink-test-prefix/lib/libnavlink.so.0\n\
                 \tlibnavlink.so (libc6,x86-64) => /opt/other/lib/libnavlink.so\n";
    assert_eq!(cached_folders(cache), [PathBuf::from(PREFIX_LIB)]);
    assert_eq!(check(Path::new(PREFIX_LIB), "pkg-config", TARGET, &no_env, cache, ""), Ok(Reach::LoaderCache));
    // Listed elsewhere, or only unversioned (the loader asks for the SONAME): not enough.
    assert!(check(Path::new("/opt/elsewhere/lib"), "pkg-config", TARGET, &no_env, cache, "").is_err());
    assert!(check(Path::new("/opt/other/lib"), "pkg-config", TARGET, &no_env, cache, "").is_err());
}

#[test]
fn rustflags_that_put_the_folder_on_the_run_path_count() {
    let dir = PREFIX_LIB;
    for flags in [
        encoded(&["-C", &format!("link-arg=-Wl,-rpath,{}", dir)]),
        encoded(&[&format!("-Clink-arg=-Wl,-rpath={}", dir)]),
        encoded(&["--cfg", "x", "-C", &format!("link-args=-Wl,--enable-new-dtags -Wl,-rpath,/elsewhere:{}/", dir)]),
        encoded(&["-C", "link-arg=-Wl,-rpath", "-C", &format!("link-arg=-Wl,{}", dir)]),
        encoded(&["-C", &format!("link-arg=-Wl,--rpath={}", dir)]),
    ] {
        assert_eq!(check(Path::new(dir), "pkg-config", TARGET, &no_env, "", &flags), Ok(Reach::Rustflags), "{:?}", flags);
    }
    // Another folder, or the folder named but not as an rpath: not enough.
    for flags in [
        encoded(&["-C", "link-arg=-Wl,-rpath,/opt/elsewhere/lib"]),
        encoded(&["-L", &format!("native={}", dir)]),
        encoded(&["-C", &format!("link-arg=-L{}", dir)]),
    ] {
        assert!(check(Path::new(dir), "pkg-config", TARGET, &no_env, "", &flags).is_err(), "{:?}", flags);
    }
    assert_eq!(rpath_folders(&encoded(&["-C", "link-arg=-Wl,-rpath,/a:/b"])), [PathBuf::from("/a"), PathBuf::from("/b")]);
    assert!(rpath_folders("").is_empty());
}

#[test]
fn navlink_run_path_loader_is_the_users_word() {
    assert_eq!(check(Path::new(PREFIX_LIB), "pkg-config", TARGET, &env_with("loader"), "", ""), Ok(Reach::SaidByUser));
    assert!(check(Path::new(PREFIX_LIB), "pkg-config", TARGET, &env_with(""), "", "").is_err());
    let error = check(Path::new(PREFIX_LIB), "pkg-config", TARGET, &env_with("yes"), "", "").unwrap_err();
    assert!(error.contains("NAVLINK_RUN_PATH") && error.contains("\"yes\"") && error.contains("`loader`"), "{}", error);
}
