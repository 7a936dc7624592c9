using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_version.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavLinkVersion
    {
        public int Major, Minor, Patch;
        public override string ToString() { return Major + "." + Minor + "." + Patch; }
    }

    /// <summary>nl_world_def. Get one from Native.nl_default_world_def(); LogFn, TaskEnqueueFn and
    /// TaskFinishFn are function pointers (native ones, or Marshal.GetFunctionPointerForDelegate of a static
    /// NativeCallbacks.LogFn / TaskEnqueueFn / TaskFinishFn).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct WorldDef
    {
        public uint Size;
        public int WorkerCount;
        public IntPtr LogFn;
        public IntPtr LogUser;
        public LogLevel LogLevel;
        public uint Reserved;
        public int PathWorkerCount;
        public IntPtr TaskEnqueueFn;
        public IntPtr TaskFinishFn;
        public IntPtr TaskUser;
        /// <summary>Agents' paths planned in one World.Step at most (default 32, at least 1); the rest wait
        /// their turn (AgentState.Waiting), oldest first.</summary>
        public uint AgentPathsPerStep;
        public uint Reserved2;
    }
}
