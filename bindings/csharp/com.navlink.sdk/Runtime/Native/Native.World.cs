using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern WorldDef nl_default_world_def();

        /// <summary>def may be null (all defaults).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_create(WorldDef* def, IntPtr* outWorld);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern void nl_world_destroy(IntPtr world);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int nl_world_get_worker_count(IntPtr world);
    }
}
