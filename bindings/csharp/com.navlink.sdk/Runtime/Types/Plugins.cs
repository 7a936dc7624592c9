using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_plugin_description. Get one from Native.nl_plugin_description_init() (Size set) before
    /// asking; the strings belong to the world.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PluginDescription
    {
        public uint Size;
        public uint AbiVersion;
        public PluginKinds Kinds;
        public uint Builtin;
        public IntPtr Name;
        public IntPtr Version;
        public IntPtr Description;
    }

    // The plugin side of the ABI (navlink/plugin.h), for plugins written in C# and registered with
    // Native.nl_plugin_register. Function pointers are IntPtr: turn the host's into delegates with
    // Marshal.GetDelegateForFunctionPointer, and fill the plugin's from static delegates kept alive for as
    // long as the world lives.

    /// <summary>nl_plugin_host: functions the host offers a plugin; Context goes back as their first argument.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PluginHost
    {
        public uint Size;
        public uint AbiVersion;
        public IntPtr Context;
        public IntPtr Log;
        public IntPtr SetError;
        public IntPtr GetLevelTriangles;
        public IntPtr NavmeshGetBoundaryEdges;
        public IntPtr NavmeshGetInfo;
        public IntPtr NavmeshFindNearest;
        public IntPtr CastRays;
        public IntPtr SegmentsBlocked;
        /// <summary>Present when Size covers it (added in 0.3).</summary>
        public IntPtr RecordBuildSettings;
        /// <summary>NativeCallbacks.HostGetBuildTrianglesFn. Present when Size covers it (added in 0.3).</summary>
        public IntPtr GetBuildTriangles;
        /// <summary>NativeCallbacks.HostReportBuildProgressFn. Present when Size covers it (added in 0.3).</summary>
        public IntPtr ReportBuildProgress;
    }

    /// <summary>nl_navmesh_builder.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshBuilder
    {
        public IntPtr Build;
    }

    /// <summary>nl_link_kind_provider.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct LinkKindProvider
    {
        public LinkKind Kind;
        public IntPtr KindName;
        public IntPtr Generate;
    }

    /// <summary>nl_plugin_info: filled by a plugin's entry function. Strings must stay valid while the
    /// plugin is loaded (allocate them with Marshal.StringToHGlobalAnsi or keep pinned UTF-8 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PluginInfo
    {
        public uint Size;
        public uint AbiVersion;
        public IntPtr Name;
        public IntPtr Version;
        public IntPtr Description;
        public PluginKinds Kinds;
        public IntPtr State;
        public IntPtr Destroy;
        public NavmeshBuilder NavmeshBuilder;
        public LinkKindProvider LinkKind;
    }
}
