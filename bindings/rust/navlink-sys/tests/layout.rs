//! navlink-sys against the C compiler's view of navlink.h, recast.h and plugin.h (build.rs compiles and
//! runs a probe over every struct and integer constant the headers define). Each struct must exist here
//! under its C name with the same size and alignment, and each field under its C name at the same offset
//! with the same size; each integer constant must exist with the same value; each inline initialiser
//! (`NL_DEFINE_OUTPUT_INIT`) must exist under its C name, return its struct with the `size` the C one
//! sets and every other field zero, and be the struct's `Default`. A struct, field, initialiser or
//! constant missing from navlink-sys does not compile, so this test fails rather than skips.
use navlink_sys as sys;
use std::mem::{align_of, size_of, MaybeUninit};

fn size_of_pointee<T>(_: *const T) -> usize {
    size_of::<T>()
}

#[test]
fn layout_matches_the_c_compiler() {
    let mut mismatches: Vec<String> = Vec::new();
    let mut structs = 0;
    let mut constants = 0;
    let mut inits = 0;

    macro_rules! c_struct {
        ($name:ident, $size:expr, $align:expr, [$(($field:ident, $offset:expr, $field_size:expr)),* $(,)?]) => {{
            structs += 1;
            if size_of::<sys::$name>() != $size || align_of::<sys::$name>() != $align {
                mismatches.push(format!("{}: size/align C {}/{}, Rust {}/{}", stringify!($name), $size, $align,
                                        size_of::<sys::$name>(), align_of::<sys::$name>()));
            }
            let value = MaybeUninit::<sys::$name>::uninit();
            let base = value.as_ptr();
            $(
                // addr_of! makes no reference to the uninitialised value.
                let field = unsafe { std::ptr::addr_of!((*base).$field) };
                let offset = field as usize - base as usize;
                let field_size = size_of_pointee(field);
                if offset != $offset || field_size != $field_size {
                    mismatches.push(format!("{}.{}: offset/size C {}/{}, Rust {}/{}", stringify!($name),
                                            stringify!($field), $offset, $field_size, offset, field_size));
                }
            )*
        }};
    }
    macro_rules! c_init {
        ($name:ident, $init:ident, $size:expr) => {{
            inits += 1;
            let value: sys::$name = sys::$init();
            if value.size != $size {
                mismatches.push(format!("{}(): size C {}, Rust {}", stringify!($init), $size, value.size));
            }
            // Every field but `size` zero (compared field by field: padding is nobody's).
            let mut zeroed: sys::$name = unsafe { std::mem::zeroed() };
            zeroed.size = value.size;
            if zeroed != value {
                mismatches.push(format!("{}(): a field other than size is not zero", stringify!($init)));
            }
            let default: sys::$name = Default::default();
            if default != value {
                mismatches.push(format!("{}::default() is not {}()", stringify!($name), stringify!($init)));
            }
        }};
    }
    macro_rules! c_constant {
        ($name:ident, $value:expr) => {{
            constants += 1;
            if sys::$name as i64 != $value {
                mismatches.push(format!("{}: C {}, Rust {}", stringify!($name), $value, sys::$name as i64));
            }
        }};
    }

    include!(concat!(env!("OUT_DIR"), "/c_layout.rs"));

    assert!(structs >= 30, "only {} structs probed", structs);
    assert!(constants >= 40, "only {} constants probed", constants);
    assert!(inits >= 11, "only {} initialisers probed", inits);
    assert!(mismatches.is_empty(), "layout differs from C:\n{}", mismatches.join("\n"));
}

#[test]
fn loaded_library_matches_the_header_version() {
    let loaded = unsafe { sys::nl_get_version() };
    assert_eq!(
        (loaded.major, loaded.minor, loaded.patch),
        (sys::NL_VERSION_MAJOR, sys::NL_VERSION_MINOR, sys::NL_VERSION_PATCH)
    );
}
