namespace NavLink
{
    // The raw C ABI: one extern per nl_* function, generated from the headers (Generated/Native.g.cs),
    // everything through the one library name below. Prefer World and its methods; this class is for what
    // they do not cover.
    public static unsafe partial class Native
    {
        // libnavlink.so on Linux/Android, libnavlink.dylib on macOS, navlink.dll on Windows: the runtime
        // adds prefix and suffix. iOS and WebGL link native code statically into the player.
#if (UNITY_IOS || UNITY_WEBGL) && !UNITY_EDITOR
        public const string Library = "__Internal";
#else
        public const string Library = "navlink";
#endif
    }
}
