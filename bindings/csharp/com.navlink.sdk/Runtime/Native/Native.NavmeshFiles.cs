using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        /// <summary>buffer: NULL only measures (two-call pattern); outSize always receives the file's size.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_save(IntPtr world, NavmeshId navmesh, byte* buffer, UIntPtr capacity,
                                                  UIntPtr* outSize);

        /// <summary>path: NUL-terminated UTF-8 (Utf8.EncodeZ).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_save_file(IntPtr world, NavmeshId navmesh, byte* path);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern NavmeshLoadDef nl_default_navmesh_load_def();

        /// <summary>def: may be null (the defaults).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_load(IntPtr world, byte* data, UIntPtr size, NavmeshLoadDef* def,
                                                  NavmeshId* outId);

        /// <summary>path: NUL-terminated UTF-8 (Utf8.EncodeZ); def: may be null (the defaults).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_load_file(IntPtr world, byte* path, NavmeshLoadDef* def, NavmeshId* outId);

        /// <summary>No world. outInfo (Size set) and madeForJson optional; outLength required with a buffer.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_file_describe(byte* data, UIntPtr size, NavmeshFileInfo* outInfo,
                                                           byte* madeForJson, UIntPtr capacity, UIntPtr* outLength);
    }
}
