using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern NavLinkVersion nl_get_version();

        /// <summary>Returns a static NUL-terminated string owned by the library.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern IntPtr nl_status_string(StatusCode status);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_get_last_status();

        /// <summary>Borrowed: valid until this thread's next nl_* call. Never null.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern IntPtr nl_get_last_error_message();
    }
}
