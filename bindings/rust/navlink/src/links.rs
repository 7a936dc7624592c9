//! Links: generation, the link store, JSON.
use crate::callbacks::{with_progress, Progress};
use crate::error::{check, Error, Result};
use crate::list::two_call_as;
use crate::types::{LinkGenerationReport, Link, LinkDef, LinkId, LinkSettings, NavmeshId};
use crate::world::World;
use navlink_sys as sys;
use std::os::raw::c_char;
use std::ptr;

/// A manual one-way link (`LinkKind::Manual`), enabled, cost modifier 1, requirements measured from its
/// ends (`requirements_as_given` false), within one navmesh (`landing_navmesh` null; `tolerance` 0.25 for
/// when it is set): set start and end. Also `LinkDef::default()` (`nl_default_link_def`).
pub fn default_link_def() -> LinkDef {
    LinkDef::default()
}

/// How to load a links JSON file (`World::load_links_json`). `Default`: only links made for the navmesh's
/// body (or for no body named).
#[derive(Clone, Copy, Debug, Default)]
pub struct LinksLoadOptions {
    /// Load links generated for another body (radius or height) than the navmesh's, with a warning to the
    /// world's log, instead of refusing them (`INVALID_ARGUMENT`) (`LINKS_LOAD_ANY_BODY`).
    pub any_body: bool,
}

impl LinksLoadOptions {
    fn flags(&self) -> u32 {
        if self.any_body { sys::NL_LINKS_LOAD_ANY_BODY } else { 0 }
    }
}

/// `Some(id)`, or `None` for the null id.
fn non_null_navmesh(id: NavmeshId) -> Option<NavmeshId> {
    if id == NavmeshId::default() {
        None
    } else {
        Some(id)
    }
}

/// A `LinkDef`'s landing navmesh (navlink.h 0.3) as an `Option`: `None` for a link within its navmesh,
/// `Some(navmesh)` for a cross link to that navmesh:
/// `LinkDef { start, end, ..default_link_def() }.with_landing(Some(deck))`.
pub trait LinkDefExt: Sized {
    /// The navmesh `end` is on, if not the link's own (`landing_navmesh`).
    fn landing(&self) -> Option<NavmeshId>;
    /// Sets `landing_navmesh`: `Some(landing)` makes a cross link from the navmesh it is added to onto
    /// `landing` (both ends given in the world as the navmeshes stand now, `end` within 1 m of `landing`;
    /// one-way only; it holds while its end, seen from its start, stays within `tolerance`); `None` the
    /// null id, a link within one navmesh.
    fn with_landing(self, landing: Option<NavmeshId>) -> Self;
}

impl LinkDefExt for LinkDef {
    fn landing(&self) -> Option<NavmeshId> {
        non_null_navmesh(self.landing_navmesh)
    }

    fn with_landing(mut self, landing: Option<NavmeshId>) -> Self {
        self.landing_navmesh = landing.unwrap_or_default();
        self
    }
}

/// A `Link`'s landing navmesh (navlink.h 0.3) as an `Option` (whether it holds now is `Link::holds`).
pub trait LinkExt {
    /// The navmesh a cross link's end is on (`landing_navmesh`); `None` for a link within its navmesh.
    fn landing(&self) -> Option<NavmeshId>;
}

impl LinkExt for Link {
    fn landing(&self) -> Option<NavmeshId> {
        non_null_navmesh(self.landing_navmesh)
    }
}

pub fn default_link_settings() -> LinkSettings {
    LinkSettings::default()
}

/// The C settings for `settings` (the defaults when `None`).
fn c_link_settings(settings: Option<&LinkSettings>) -> sys::nl_link_settings {
    let defaults = unsafe { sys::nl_default_link_settings() };
    settings.map_or(defaults, |s| s.to_c(defaults))
}

/// The C def for `def`, over the header's defaults.
fn c_link_def(def: &LinkDef) -> sys::nl_link_def {
    def.to_c(unsafe { sys::nl_default_link_def() })
}

/// Applies a JSON object's keys to `base` (the defaults when `None`) and validates the result.
pub fn link_settings_from_json(json: &str, base: Option<LinkSettings>) -> Result<LinkSettings> {
    let mut settings = c_link_settings(base.as_ref());
    check(unsafe { sys::nl_link_settings_from_json(non_null(json), json.len(), &mut settings) })?;
    Ok(settings.into())
}

/// A pointer to the text, never null (an empty string is still "given").
fn non_null(text: &str) -> *const c_char {
    if text.is_empty() {
        b"\0".as_ptr().cast()
    } else {
        text.as_ptr().cast()
    }
}

impl World {
    /// Adds a link to `navmesh`: both ends within 1 m of it, or, with a landing navmesh
    /// ([`LinkDefExt::with_landing`]), the start within 1 m of `navmesh` and the end within 1 m of the
    /// landing one. `INVALID_ARGUMENT` for a two-way cross link or one that lands on its own navmesh,
    /// `INVALID_HANDLE` for a stale landing navmesh.
    pub fn add_link(&self, navmesh: NavmeshId, def: &LinkDef) -> Result<LinkId> {
        let def = c_link_def(def);
        let mut id = LinkId::default();
        check(unsafe { sys::nl_link_add(self.raw(), navmesh, &def, &mut id) })?;
        Ok(id)
    }

    /// Replaces the link's fields with `def`'s (errors as `add_link`).
    pub fn update_link(&self, link: LinkId, def: &LinkDef) -> Result<()> {
        let def = c_link_def(def);
        check(unsafe { sys::nl_link_update(self.raw(), link, &def) }).map(drop)
    }

    pub fn remove_link(&self, link: LinkId) -> Result<()> {
        check(unsafe { sys::nl_link_remove(self.raw(), link) }).map(drop)
    }

    pub fn is_link_valid(&self, link: LinkId) -> bool {
        unsafe { sys::nl_link_is_valid(self.raw(), link) != 0 }
    }

    pub fn link(&self, link: LinkId) -> Result<Link> {
        let mut out = sys::nl_link_init();
        check(unsafe { sys::nl_link_get(self.raw(), link, &mut out) })?;
        Ok(out.into())
    }

    /// The navmesh's links (generated and manual), in the order they were added.
    pub fn links(&self, navmesh: NavmeshId) -> Result<Vec<Link>> {
        // two_call's buffer is of nl_link::default(), whose size tells the library the element size.
        two_call_as(|buffer, capacity, count| unsafe { sys::nl_navmesh_get_links(self.raw(), navmesh, buffer, capacity, count) })
    }

    /// Removes the navmesh's generated links; returns how many went.
    pub fn remove_generated_links(&self, navmesh: NavmeshId) -> Result<u32> {
        let mut removed = 0;
        check(unsafe { sys::nl_navmesh_remove_generated_links(self.raw(), navmesh, &mut removed) })?;
        Ok(removed)
    }

    /// Generates the navmesh's jump and drop links (and plugin kinds'), replacing the generated ones.
    /// `plugin_settings_json` fills the settings' plugin_settings_json. A progress closure returning false
    /// cancels (an `Error` with CANCELLED); one that panics cancels too, and the panic resumes here.
    pub fn generate_links(
        &self,
        navmesh: NavmeshId,
        settings: Option<&LinkSettings>,
        plugin_settings_json: Option<&str>,
        progress: Option<Progress<'_>>,
    ) -> Result<LinkGenerationReport> {
        let mut settings = c_link_settings(settings);
        if let Some(json) = plugin_settings_json {
            settings.plugin_settings_json = non_null(json);
            settings.plugin_settings_json_length = json.len();
        }
        let mut report = sys::nl_link_generation_report_init();
        with_progress(progress, |function, user| unsafe {
            sys::nl_navmesh_generate_links(self.raw(), navmesh, &settings, function, user, &mut report)
        })?;
        Ok(report.into())
    }

    /// Generates the jump and drop links between two navmeshes (a ledge and a platform; either may ride a
    /// moving mesh) for where they stand now, both ways, as cross links that hold while the two stay placed
    /// so, within `tolerance` metres (0.25 is a good start). They replace the generated cross links between
    /// the two that hold now; those made for another placement (a platform's other stop) stay, and so do
    /// each navmesh's own links. Both navmeshes must be made for the same agent radius and height.
    /// `settings` and `progress` as for `generate_links` (no plugin kinds run here); the report's
    /// `jump_links` and `drop_links` count the cross links made. `INVALID_ARGUMENT` for the same navmesh
    /// twice, different bodies, a bad tolerance or setting; `INVALID_HANDLE` for either navmesh stale;
    /// `CANCELLED` (nothing changed).
    pub fn generate_cross_links(
        &self,
        first: NavmeshId,
        second: NavmeshId,
        tolerance: f32,
        settings: Option<&LinkSettings>,
        progress: Option<Progress<'_>>,
    ) -> Result<LinkGenerationReport> {
        let settings = c_link_settings(settings);
        let mut report = sys::nl_link_generation_report_init();
        with_progress(progress, |function, user| unsafe {
            sys::nl_navmesh_generate_cross_links(self.raw(), first, second, tolerance, &settings, function, user, &mut report)
        })?;
        Ok(report.into())
    }

    /// Regenerates only what geometry changes inside `[box_min, box_max]` can have affected.
    pub fn update_links_in_box(
        &self,
        navmesh: NavmeshId,
        box_min: [f32; 3],
        box_max: [f32; 3],
        progress: Option<Progress<'_>>,
    ) -> Result<LinkGenerationReport> {
        let mut report = sys::nl_link_generation_report_init();
        with_progress(progress, |function, user| unsafe {
            sys::nl_navmesh_update_links_in_box(self.raw(), navmesh, box_min.as_ptr(), box_max.as_ptr(), function, user, &mut report)
        })?;
        Ok(report.into())
    }

    /// The navmesh's links as JSON (schema "navlink-links" version 1); `INVALID_ARGUMENT` for a navmesh
    /// with cross links (links files hold the links within one navmesh).
    pub fn save_links_json(&self, navmesh: NavmeshId) -> Result<String> {
        loop {
            let mut length = 0usize;
            check(unsafe { sys::nl_navmesh_save_links_json(self.raw(), navmesh, ptr::null_mut(), 0, &mut length) })?;
            let mut buffer = vec![0u8; length + 1];
            let status = unsafe {
                sys::nl_navmesh_save_links_json(self.raw(), navmesh, buffer.as_mut_ptr().cast(), buffer.len(), &mut length)
            };
            if sys::nl_failed(status) && status & sys::NL_STATUS_BUFFER_TOO_SMALL != 0 {
                continue; // the links changed between the two calls
            }
            check(status)?;
            buffer.truncate(length);
            return String::from_utf8(buffer)
                .map_err(|_| Error::binding(sys::NL_STATUS_INTERNAL_ERROR, "links JSON is not UTF-8".into()));
        }
    }

    /// Replaces all of the navmesh's links with those in `json`; returns how many were loaded. A file that
    /// records the body its links were generated for (`"made_for"`) must name the navmesh's (radius and
    /// height): links for another body are refused (`INVALID_ARGUMENT`, both bodies named) unless
    /// `options.any_body`. Files without `"made_for"` load whatever the body. On failure nothing changes.
    pub fn load_links_json(&self, navmesh: NavmeshId, json: &str, options: &LinksLoadOptions) -> Result<u32> {
        let mut count = 0;
        check(unsafe {
            sys::nl_navmesh_load_links_json(self.raw(), navmesh, non_null(json), json.len(), options.flags(), &mut count)
        })?;
        Ok(count)
    }
}
