using System;
using System.Runtime.InteropServices;
using System.Text;

namespace NavLink
{
    // Strings cross the ABI as UTF-8 (navlink.h). Encoded by hand rather than by the marshaller, whose
    // default for `string` is the platform's ANSI code page on Windows.
    public static class Utf8
    {
        /// <summary>NUL-terminated UTF-8 bytes of s, or null for a null string.</summary>
        public static byte[] EncodeZ(string s)
        {
            if (s == null) return null;
            int n = Encoding.UTF8.GetByteCount(s);
            var bytes = new byte[n + 1];
            Encoding.UTF8.GetBytes(s, 0, s.Length, bytes, 0);
            return bytes;
        }

        /// <summary>The string at a borrowed NUL-terminated UTF-8 pointer (null for IntPtr.Zero).</summary>
        public static unsafe string Decode(IntPtr p)
        {
            if (p == IntPtr.Zero) return null;
            byte* s = (byte*)p;
            int n = 0;
            while (s[n] != 0) ++n;
            return Encoding.UTF8.GetString(s, n);
        }

        /// <summary>The string in a NUL-terminated UTF-8 char array of `capacity` bytes (a struct's fixed
        /// buffer); all of it when no NUL comes first.</summary>
        public static unsafe string Decode(byte* s, int capacity)
        {
            int n = 0;
            while (n < capacity && s[n] != 0) ++n;
            return Encoding.UTF8.GetString(s, n);
        }

        /// <summary>Copies s into unmanaged memory as NUL-terminated UTF-8, for strings a plugin must
        /// keep alive (free with Marshal.FreeHGlobal).</summary>
        public static IntPtr AllocZ(string s)
        {
            byte[] bytes = EncodeZ(s);
            IntPtr p = Marshal.AllocHGlobal(bytes.Length);
            Marshal.Copy(bytes, 0, p, bytes.Length);
            return p;
        }
    }
}
