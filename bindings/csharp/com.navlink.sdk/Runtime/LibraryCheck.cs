using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // The first call into libnavlink loads it. When that fails the runtime throws DllNotFoundException
    // naming only "navlink"; this turns it into a NavLinkException that says what was looked for, on which
    // platform, and where to put the library. Called where the idiomatic layer first touches the library:
    // World, WorldOptions, PathQuery, NavmeshInput and World's static helpers.
    internal static class LibraryCheck
    {
        // 0: not tried, 1: loaded. A failed load is tried again next time (the host may fix the path).
        private static volatile int loaded;

        internal static void EnsureLoaded()
        {
            if (loaded != 0) return;
            try
            {
                Native.nl_get_version();
            }
            catch (DllNotFoundException e)
            {
                throw new NavLinkException(StatusCode.Failure | StatusCode.NotFound, MissingLibraryMessage(e), e);
            }
            catch (EntryPointNotFoundException e)
            {
                throw new NavLinkException(StatusCode.Failure | StatusCode.VersionMismatch,
                    "NavLink: a library named \"" + Native.Library + "\" was loaded but has no nl_get_version: it is not " +
                    "libnavlink, or one older than this binding (written for " + HeaderVersion.Major + "." +
                    HeaderVersion.Minor + "." + HeaderVersion.Patch + "). " + WhereToPutIt(), e);
            }
            loaded = 1;
        }

        internal static string MissingLibraryMessage(Exception cause)
        {
            return "NavLink: cannot load the native library: [DllImport(\"" + Native.Library + "\")] looked for " +
                   FileName() + " on " + PlatformName() + " and did not find it (" + cause.GetType().Name + ": " +
                   cause.Message + "). " + WhereToPutIt();
        }

        // What the runtime turns the DllImport name into.
        private static string FileName()
        {
#if (UNITY_IOS || UNITY_WEBGL) && !UNITY_EDITOR
            return "its functions linked statically into the player (\"__Internal\")";
#else
            if (RuntimeInformation.IsOSPlatform(OSPlatform.Windows)) return Native.Library + ".dll";
            if (RuntimeInformation.IsOSPlatform(OSPlatform.OSX)) return "lib" + Native.Library + ".dylib";
            return "lib" + Native.Library + ".so";
#endif
        }

        private static string PlatformName()
        {
#if UNITY_ANDROID && !UNITY_EDITOR
            const string os = "Android";
#elif (UNITY_IOS || UNITY_WEBGL) && !UNITY_EDITOR
            const string os = "iOS or WebGL";
#else
            string os = RuntimeInformation.IsOSPlatform(OSPlatform.Windows) ? "Windows"
                      : RuntimeInformation.IsOSPlatform(OSPlatform.OSX) ? "macOS"
                      : RuntimeInformation.IsOSPlatform(OSPlatform.Linux) ? "Linux" : RuntimeInformation.OSDescription;
#endif
            return os + " " + RuntimeInformation.ProcessArchitecture + " (" + RuntimeInformation.FrameworkDescription + ")";
        }

        private static string WhereToPutIt()
        {
#if UNITY_5_3_OR_NEWER
            // Unity: the editor and players load plugins the Plugins folder's import settings enable.
            return "In Unity, put the library for each platform in the package's Plugins/ folder (or Assets/Plugins/) " +
                   "and enable it in the Inspector's import settings for that platform and CPU (Plugins/README.md); " +
                   "iOS and WebGL link libnavlink.a into the player instead.";
#else
            string search = RuntimeInformation.IsOSPlatform(OSPlatform.Windows) ? "a folder on PATH"
                          : RuntimeInformation.IsOSPlatform(OSPlatform.OSX) ? "a folder on DYLD_LIBRARY_PATH"
                          : "a folder on LD_LIBRARY_PATH";
            // Mono reads NavLink.dll.config beside NavLink.dll; NavLink.csproj writes it (write_dll_config.sh).
            return "With Mono, NavLink.dll.config beside NavLink.dll maps the name to the library: <dllmap dll=\"" +
                   Native.Library + "\" target=\"/path/to/" + FileName() + "\"/>; NavLink.csproj writes it when it builds " +
                   "NavLink.dll, from /p:NavLinkLibraryDir=DIR or else pkg-config's navlink.pc, so rebuild it if the library " +
                   "moved. Otherwise put " + FileName() + " next to the executable (or NavLink.dll) or in " + search +
                   ". In Unity, put it in the package's Plugins/ folder (Plugins/README.md).";
#endif
        }
    }
}
