//! Plugins: load, register, describe, list.
use crate::error::{borrowed_str, check, Result};
use crate::level::{c_string, path_bytes};
use crate::list::two_call;
use crate::types::PluginId;
use crate::world::World;
use navlink_sys as sys;
use std::path::Path;

/// What a loaded plugin is (`nl_plugin_description`, strings copied).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PluginSummary {
    pub name: String,
    pub version: String,
    pub description: String,
    pub kinds: u32,
    pub builtin: bool,
    pub abi_version: u32,
}

impl World {
    /// Loads a plugin library into the world.
    ///
    /// # Safety
    /// Loading a shared library runs its initialisers, and the world then calls its code: it must be a
    /// NavLink plugin that keeps to navlink/plugin.h.
    pub unsafe fn load_plugin(&self, path: impl AsRef<Path>) -> Result<PluginId> {
        let path = c_string(&path_bytes(path.as_ref()), "path")?;
        let mut id = PluginId::default();
        check(sys::nl_plugin_load(self.raw(), path.as_ptr(), &mut id))?;
        Ok(id)
    }

    /// Registers a plugin compiled into this program, through its entry function.
    ///
    /// # Safety
    /// `entry` and every function it hands over must keep to navlink/plugin.h, and stay callable (with
    /// what they point to) until the world is dropped.
    pub unsafe fn register_plugin(&self, entry: sys::nl_plugin_entry_fn) -> Result<PluginId> {
        let mut id = PluginId::default();
        check(sys::nl_plugin_register(self.raw(), entry, &mut id))?;
        Ok(id)
    }

    pub fn plugin_description(&self, plugin: PluginId) -> Result<PluginSummary> {
        let mut d = sys::nl_plugin_description_init();
        check(unsafe { sys::nl_plugin_get_description(self.raw(), plugin, &mut d) })?;
        // The strings belong to the world; copied while it is borrowed.
        unsafe {
            Ok(PluginSummary {
                name: borrowed_str(d.name),
                version: borrowed_str(d.version),
                description: borrowed_str(d.description),
                kinds: d.kinds,
                builtin: d.builtin != 0,
                abi_version: d.abi_version,
            })
        }
    }

    /// The world's plugins, built-in ones first.
    pub fn plugins(&self) -> Result<Vec<PluginId>> {
        two_call(|buffer, capacity, count| unsafe { sys::nl_world_get_plugins(self.raw(), buffer, capacity, count) })
    }
}
