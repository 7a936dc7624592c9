using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern LinkDef nl_default_link_def();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_link_add(IntPtr world, NavmeshId navmesh, LinkDef* def, LinkId* outId);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_link_update(IntPtr world, LinkId link, LinkDef* def);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_link_remove(IntPtr world, LinkId link);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int nl_link_is_valid(IntPtr world, LinkId link);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_link_get(IntPtr world, LinkId link, Link* outLink);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_links(IntPtr world, NavmeshId navmesh, Link* outLinks, uint capacity,
                                                       uint* outCount);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_remove_generated_links(IntPtr world, NavmeshId navmesh, uint* outRemoved);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern LinkSettings nl_default_link_settings();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_link_settings_from_json(byte* json, UIntPtr length, LinkSettings* settings);

        /// <summary>progress: a static NativeCallbacks.ProgressFn as a function pointer, or IntPtr.Zero.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_generate_links(IntPtr world, NavmeshId navmesh, LinkSettings* settings,
                                                            IntPtr progress, IntPtr user, LinkGenerationReport* outReport);

        /// <summary>progress: as for nl_navmesh_generate_links.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_generate_cross_links(IntPtr world, NavmeshId first, NavmeshId second,
                                                                  float tolerance, LinkSettings* settings, IntPtr progress,
                                                                  IntPtr user, LinkGenerationReport* outReport);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_update_links_in_box(IntPtr world, NavmeshId navmesh, float* boxMin,
                                                                 float* boxMax, IntPtr progress, IntPtr user,
                                                                 LinkGenerationReport* outReport);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_save_links_json(IntPtr world, NavmeshId navmesh, byte* buffer,
                                                             UIntPtr capacity, UIntPtr* outLength);

        /// <summary>flags: LinksLoadFlags.AnyBody or 0.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_load_links_json(IntPtr world, NavmeshId navmesh, byte* json,
                                                             UIntPtr length, LinksLoadFlags flags, uint* outCount);
    }
}
