//! navlink-sys links libnavlink.so; an rpath only reaches the binaries of the package that asks for it,
//! so this crate's tests ask too, with the folder navlink-sys found (DEP_NAVLINK_LIB_DIR).
fn main() {
    println!("cargo:rerun-if-env-changed=DEP_NAVLINK_LIB_DIR");
    if let Ok(dir) = std::env::var("DEP_NAVLINK_LIB_DIR") {
        println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir);
    }
}
