//! build.rs's library lookup (build/find_library.rs), run as a function: the environment is a map the
//! test writes, pkg-config is the real program pointed at a folder holding a navlink.pc written here.
#[path = "../build/find_library.rs"]
#[allow(dead_code)]
mod find_library;

use find_library::{find, library_file, Linking, PkgConfig};
use std::collections::HashMap;
use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};

/// A fresh folder under the system's temp folder, removed when dropped.
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("navlink-sys-{}-{}", name, std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

/// An installed NavLink's shape: PREFIX/lib/<library file>, PREFIX/include, and a navlink.pc in
/// PREFIX/lib/pkgconfig as capi/CMakeLists.txt installs it (relocatable through ${pcfiledir}), with
/// `Libs.private` when given.
fn fake_install(prefix: &Path, library: &str, libs_private: Option<&str>) -> PathBuf {
    let pc_dir = prefix.join("lib/pkgconfig");
    fs::create_dir_all(&pc_dir).unwrap();
    fs::create_dir_all(prefix.join("include")).unwrap();
    fs::write(prefix.join("lib").join(library), b"").unwrap();
    let mut pc = String::from(
        "prefix=${pcfiledir}/../..\nlibdir=${prefix}/lib\nincludedir=${prefix}/include\n\n\
         Name: NavLink\nDescription: test\nVersion: 0.2.0\nLibs: -L${libdir} -lnavlink\nCflags: -I${includedir}\n",
    );
    if let Some(libs) = libs_private {
        pc.push_str(&format!("Libs.private: {}\n", libs));
    }
    fs::write(pc_dir.join("navlink.pc"), pc).unwrap();
    pc_dir
}

/// pkg-config that searches `pc_dir` only (PKG_CONFIG_LIBDIR replaces the system folders, so an
/// installed NavLink on this machine cannot answer in place of the test's).
fn pkg_config_in(pc_dir: &Path) -> PkgConfig {
    PkgConfig {
        program: "pkg-config".into(),
        env: vec![("PKG_CONFIG_PATH".into(), pc_dir.into()), ("PKG_CONFIG_LIBDIR".into(), pc_dir.into())],
    }
}

fn env_of(vars: &[(&str, &Path)]) -> impl Fn(&str) -> Option<OsString> {
    let map: HashMap<String, OsString> = vars.iter().map(|(k, v)| (k.to_string(), v.as_os_str().to_owned())).collect();
    move |name| map.get(name).cloned()
}

const SHARED: &str = "libnavlink.so";

#[test]
fn navlink_lib_dir_comes_before_pkg_config() {
    let build = TempDir::new("env-first-build");
    fs::write(build.0.join(SHARED), b"").unwrap();
    let installed = TempDir::new("env-first-installed");
    let pc_dir = fake_install(&installed.0, SHARED, None);
    let found = find(&env_of(&[("NAVLINK_LIB_DIR", &build.0)]), &pkg_config_in(&pc_dir), "linux", Linking::Shared, Path::new("/none"))
        .unwrap();
    assert_eq!((found.lib_dir, found.origin), (build.0.clone(), "NAVLINK_LIB_DIR"));
    assert!(found.include_dirs.is_empty() && found.static_deps.is_empty(), "{:?} {:?}", found.include_dirs, found.static_deps);
}

#[test]
fn navlink_lib_dir_without_the_library_is_refused_by_name() {
    let empty = TempDir::new("env-empty");
    let installed = TempDir::new("env-empty-installed");
    let pc_dir = fake_install(&installed.0, SHARED, None);
    let error = find(&env_of(&[("NAVLINK_LIB_DIR", &empty.0)]), &pkg_config_in(&pc_dir), "linux", Linking::Shared, Path::new("/none"))
        .unwrap_err();
    assert!(error.contains("NAVLINK_LIB_DIR") && error.contains(&empty.0.display().to_string()) && error.contains(SHARED), "{}", error);
}

#[test]
fn pkg_config_finds_an_installed_library_and_its_headers() {
    let installed = TempDir::new("pc-found");
    let pc_dir = fake_install(&installed.0, SHARED, None);
    let found = find(&env_of(&[]), &pkg_config_in(&pc_dir), "linux", Linking::Shared, Path::new("/none")).unwrap();
    assert_eq!(found.origin, "pkg-config");
    // pkg-config resolves ${pcfiledir}/../.. as text: compare the folders themselves.
    assert_eq!(fs::canonicalize(&found.lib_dir).unwrap(), fs::canonicalize(installed.0.join("lib")).unwrap());
    assert_eq!(found.include_dirs.len(), 1, "{:?}", found.include_dirs);
    assert_eq!(fs::canonicalize(&found.include_dirs[0]).unwrap(), fs::canonicalize(installed.0.join("include")).unwrap());
}

#[test]
fn a_pc_file_whose_libdir_lacks_the_library_is_not_taken() {
    let installed = TempDir::new("pc-no-lib");
    let pc_dir = fake_install(&installed.0, SHARED, None);
    fs::remove_file(installed.0.join("lib").join(SHARED)).unwrap();
    let error = find(&env_of(&[]), &pkg_config_in(&pc_dir), "linux", Linking::Shared, Path::new("/none")).unwrap_err();
    assert!(error.contains("libdir") && error.contains(SHARED), "{}", error);
}

#[test]
fn nothing_found_says_what_to_set() {
    let nowhere = TempDir::new("nothing");
    let source_build = TempDir::new("nothing-source-build");
    let error = find(&env_of(&[]), &pkg_config_in(&nowhere.0), "linux", Linking::Shared, &source_build.0).unwrap_err();
    for needed in ["NAVLINK_LIB_DIR", "PKG_CONFIG_PATH", "cmake --install", "pkg-config", SHARED] {
        assert!(error.contains(needed), "no {:?} in:\n{}", needed, error);
    }
    // A source tree without a built library is not suggested; one with it is.
    assert!(!error.contains("This source tree"), "{}", error);
    fs::write(source_build.0.join(SHARED), b"").unwrap();
    let error = find(&env_of(&[]), &pkg_config_in(&nowhere.0), "linux", Linking::Shared, &source_build.0).unwrap_err();
    assert!(error.contains(&format!("NAVLINK_LIB_DIR={}", source_build.0.display())), "{}", error);
}

#[test]
fn a_missing_pkg_config_program_is_named() {
    let nowhere = TempDir::new("no-program");
    let pkg_config = PkgConfig { program: nowhere.0.join("no-such-pkg-config").into(), env: Vec::new() };
    let error = find(&env_of(&[]), &pkg_config, "linux", Linking::Shared, Path::new("/none")).unwrap_err();
    assert!(error.contains("no-such-pkg-config") && error.contains("NAVLINK_LIB_DIR"), "{}", error);
}

#[test]
fn static_linking_takes_the_deps_from_the_environment_the_pc_file_or_the_defaults() {
    let installed = TempDir::new("static");
    let static_file = library_file("linux", Linking::Static);
    let pc_dir = fake_install(&installed.0, static_file, Some("-lstdc++ -ltbb -lm"));
    let found = find(&env_of(&[]), &pkg_config_in(&pc_dir), "linux", Linking::Static, Path::new("/none")).unwrap();
    assert_eq!(found.static_deps, ["stdc++", "tbb", "m"]);

    let libs = PathBuf::from("c++ tbb12");
    let found = find(&env_of(&[("NAVLINK_STATIC_LIBS", &libs)]), &pkg_config_in(&pc_dir), "linux", Linking::Static, Path::new("/none"))
        .unwrap();
    assert_eq!(found.static_deps, ["c++", "tbb12"]);

    let bare = TempDir::new("static-bare");
    let pc_dir = fake_install(&bare.0, static_file, None);
    let found = find(&env_of(&[]), &pkg_config_in(&pc_dir), "linux", Linking::Static, Path::new("/none")).unwrap();
    // The fallback is every library a static build's navlink.pc lists (`pkg-config --static --libs-only-l
    // navlink` after -lnavlink: Libs.private, then Requires.private's tbb and zlib), so that linking
    // libnavlink.a without pkg-config leaves no symbol undefined.
    assert_eq!(found.static_deps, ["embree3", "Recast", "DetourCrowd", "Detour", "tbb", "z", "dl", "stdc++", "m"]);
    let position = |library: &str| found.static_deps.iter().position(|l| l == library).unwrap();
    assert!(position("embree3") < position("tbb"), "Embree needs oneTBB after it: {:?}", found.static_deps);
    // The shared library is not what a static build looks for.
    let shared_only = TempDir::new("static-shared-only");
    let pc_dir = fake_install(&shared_only.0, SHARED, None);
    assert!(find(&env_of(&[]), &pkg_config_in(&pc_dir), "linux", Linking::Static, Path::new("/none")).is_err());
}
