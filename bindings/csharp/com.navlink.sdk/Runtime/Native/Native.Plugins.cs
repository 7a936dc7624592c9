using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        /// <summary>path: NUL-terminated UTF-8.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_plugin_load(IntPtr world, byte* path, PluginId* outId);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_plugin_get_description(IntPtr world, PluginId plugin,
                                                            PluginDescription* outDescription);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_get_plugins(IntPtr world, PluginId* outIds, uint capacity, uint* outCount);

        /// <summary>navlink/plugin.h. entry: a static NativeCallbacks.PluginEntryFn as a function pointer.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_plugin_register(IntPtr world, IntPtr entry, PluginId* outId);
    }
}
