using System;
using System.Runtime.InteropServices;
using System.Text;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>A manual one-way link, enabled, cost modifier 1, requirements measured from its ends
        /// (RequirementsAsGiven 0), within one navmesh (LandingNavmesh null; Tolerance 0.25 for when it is
        /// set): set Start and End.</summary>
        public static LinkDef DefaultLinkDef() { LibraryCheck.EnsureLoaded(); return Native.nl_default_link_def(); }

        public static LinkSettings DefaultLinkSettings() { LibraryCheck.EnsureLoaded(); return Native.nl_default_link_settings(); }

        /// <summary>Applies a JSON object's keys to settings (defaults when null) and validates them.</summary>
        public static unsafe LinkSettings LinkSettingsFromJson(string json, LinkSettings? baseSettings = null)
        {
            LibraryCheck.EnsureLoaded();
            LinkSettings settings = baseSettings ?? Native.nl_default_link_settings();
            byte[] utf8 = Encoding.UTF8.GetBytes(json ?? "");
            byte empty = 0;
            fixed (byte* j = utf8)
                Status.Check(Native.nl_link_settings_from_json(utf8.Length == 0 ? &empty : j, (UIntPtr)utf8.Length,
                                                               &settings));
            return settings;
        }

        /// <summary>Adds a link to a navmesh: both ends within 1 m of it, or, with def.LandingNavmesh set (a
        /// cross link), the start within 1 m of navmesh and the end within 1 m of the landing navmesh, both
        /// given in the world as the navmeshes stand now. A cross link is one-way (Bidirectional refused,
        /// InvalidArgument) and leads to another navmesh (its own refused, InvalidArgument); a stale
        /// LandingNavmesh is InvalidHandle.</summary>
        public unsafe LinkId AddLink(NavmeshId navmesh, LinkDef def)
        {
            LinkId id;
            using (var w = Enter()) Status.Check(Native.nl_link_add(w.Pointer, navmesh, &def, &id));
            return id;
        }

        /// <summary>Replaces a link's fields with def's (errors as AddLink).</summary>
        public unsafe void UpdateLink(LinkId link, LinkDef def)
        {
            using (var w = Enter()) Status.Check(Native.nl_link_update(w.Pointer, link, &def));
        }

        public void RemoveLink(LinkId link)
        {
            using (var w = Enter()) Status.Check(Native.nl_link_remove(w.Pointer, link));
        }

        public bool IsValid(LinkId link)
        {
            using (var w = Enter()) return Native.nl_link_is_valid(w.Pointer, link) != 0;
        }

        public Link GetLink(LinkId link)
        {
            Link result;
            if (!TryGetLink(link, out result))
                throw new NavLinkException(Native.nl_get_last_status(), Status.LastErrorMessage());
            return result;
        }

        /// <summary>False for a null, stale or foreign id.</summary>
        public unsafe bool TryGetLink(LinkId link, out Link result)
        {
            Link found = Native.nl_link_init();
            StatusCode status;
            using (var w = Enter()) status = Native.nl_link_get(w.Pointer, link, &found);
            if (Status.Failed(status) && (status & StatusCode.InvalidHandle) != 0)
            {
                result = default(Link);
                return false;
            }
            Status.Check(status);
            result = found;
            return true;
        }

        /// <summary>The navmesh's links (generated and manual) in the order they were added.</summary>
        public unsafe Link[] GetLinks(NavmeshId navmesh)
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<Link>((buffer, capacity, count) =>
                    Native.nl_navmesh_get_links(world, navmesh, (Link*)buffer, capacity, count), Native.nl_link_init());
            }
        }

        /// <summary>Removes the generated links; returns how many went.</summary>
        public unsafe uint RemoveGeneratedLinks(NavmeshId navmesh)
        {
            uint removed;
            using (var w = Enter()) Status.Check(Native.nl_navmesh_remove_generated_links(w.Pointer, navmesh, &removed));
            return removed;
        }

        /// <summary>Generates the navmesh's jump and drop links (replacing the generated ones).
        /// progress returning false cancels (NavLinkException with Cancelled); an exception thrown by
        /// progress cancels the generation and is rethrown here.</summary>
        public unsafe LinkGenerationReport GenerateLinks(NavmeshId navmesh, LinkSettings? settings = null,
                                               ProgressHandler progress = null, string pluginSettingsJson = null)
        {
            LinkSettings s = settings ?? Native.nl_default_link_settings();
            byte[] json = pluginSettingsJson == null ? null : Encoding.UTF8.GetBytes(pluginSettingsJson);
            LinkGenerationReport report = Native.nl_link_generation_report_init();
            byte empty = 0;
            fixed (byte* j = json)
            {
                if (json != null)
                {
                    s.PluginSettingsJson = json.Length == 0 ? (IntPtr)(&empty) : (IntPtr)j;
                    s.PluginSettingsJsonLength = (UIntPtr)json.Length;
                }
                using (var scope = new ProgressScope(progress))
                using (var w = Enter())
                    scope.Check(Native.nl_navmesh_generate_links(w.Pointer, navmesh, &s, scope.Function, scope.User,
                                                                 &report));
            }
            return report;
        }

        /// <summary>Generates the jump and drop links between two navmeshes (a ledge and a platform; either
        /// may ride a moving mesh) for where they stand now, both ways, as cross links (Link.LandingNavmesh)
        /// that hold while the two stay placed so, within tolerance metres (0.25 is a good start). They
        /// replace the generated cross links between the two that hold now; those made for another placement
        /// (a platform's other stop) stay, and so do each navmesh's own links. Both navmeshes must be made
        /// for the same agent radius and height. settings and progress as for GenerateLinks (no plugin kinds
        /// run here); the report's JumpLinks and DropLinks count the cross links made. InvalidArgument for
        /// the same navmesh twice, different bodies, a bad tolerance or setting; InvalidHandle for either
        /// navmesh stale; Cancelled (nothing changed).</summary>
        public unsafe LinkGenerationReport GenerateCrossLinks(NavmeshId first, NavmeshId second, float tolerance,
                                                              LinkSettings? settings = null, ProgressHandler progress = null)
        {
            LinkSettings s = settings ?? Native.nl_default_link_settings();
            LinkGenerationReport report = Native.nl_link_generation_report_init();
            using (var scope = new ProgressScope(progress))
            using (var w = Enter())
                scope.Check(Native.nl_navmesh_generate_cross_links(w.Pointer, first, second, tolerance, &s, scope.Function,
                                                                   scope.User, &report));
            return report;
        }

        /// <summary>Regenerates only what geometry changes inside [boxMin, boxMax] can have affected.</summary>
        public unsafe LinkGenerationReport UpdateLinksInBox(NavmeshId navmesh, Vec3 boxMin, Vec3 boxMax, ProgressHandler progress = null)
        {
            LinkGenerationReport report = Native.nl_link_generation_report_init();
            using (var scope = new ProgressScope(progress))
            using (var w = Enter())
                scope.Check(Native.nl_navmesh_update_links_in_box(w.Pointer, navmesh, (float*)&boxMin, (float*)&boxMax,
                                                                  scope.Function, scope.User, &report));
            return report;
        }

        /// <summary>The navmesh's links as JSON (schema "navlink-links" version 1). InvalidArgument for a
        /// navmesh with cross links (links files hold links within one navmesh).</summary>
        public unsafe string SaveLinksJson(NavmeshId navmesh)
        {
            using (var w = Enter())
            {
                while (true)
                {
                    UIntPtr length;
                    Status.Check(Native.nl_navmesh_save_links_json(w.Pointer, navmesh, null, UIntPtr.Zero, &length));
                    var buffer = new byte[(ulong)length + 1];
                    StatusCode status;
                    fixed (byte* b = buffer)
                        status = Native.nl_navmesh_save_links_json(w.Pointer, navmesh, b, (UIntPtr)buffer.Length, &length);
                    if (Status.IsBufferTooSmall(status)) continue;  // links changed
                    Status.Check(status);
                    return Encoding.UTF8.GetString(buffer, 0, (int)(ulong)length);
                }
            }
        }

        /// <summary>Replaces all of the navmesh's links with those in json; returns how many were loaded.
        /// A file that records the body its links were generated for ("made_for") must name the navmesh's
        /// (radius and height): links for another body are refused (InvalidArgument, both bodies named)
        /// unless anyBody (LinksLoadFlags.AnyBody), which loads them with a warning to the world's log.
        /// Files without "made_for" load whatever the body. On failure nothing changes.</summary>
        public unsafe uint LoadLinksJson(NavmeshId navmesh, string json, bool anyBody = false)
        {
            LinksLoadFlags flags = anyBody ? LinksLoadFlags.AnyBody : LinksLoadFlags.None;
            byte[] utf8 = Encoding.UTF8.GetBytes(json ?? "");
            uint count;
            byte empty = 0;
            fixed (byte* j = utf8)
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_load_links_json(w.Pointer, navmesh, utf8.Length == 0 ? &empty : j,
                                                               (UIntPtr)utf8.Length, flags, &count));
            return count;
        }
    }
}
