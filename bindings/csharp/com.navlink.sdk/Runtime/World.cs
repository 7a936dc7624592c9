using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>How to create a World (nl_world_def).</summary>
    public sealed class WorldOptions
    {
        /// <summary>Threads for batch work, the caller included; Limits.WorkersAuto: one per hardware thread.</summary>
        public int WorkerCount = Limits.WorkersAuto;
        /// <summary>Threads planning queued path requests; 0: the host runs the queue with ProcessPaths.</summary>
        public int PathWorkerCount = Limits.WorkersAuto;
        /// <summary>Receives failures (and by LogLevel warnings...) of calls on this world, on the calling
        /// thread or a NavLink worker: must be thread-safe and must not call into the world.</summary>
        public LogHandler Log;
        public LogLevel LogLevel = LogLevel.Warning;
        /// <summary>A host task system (navlink.h: nl_task_enqueue_fn, nl_task_finish_fn), both or neither:
        /// the world's batch work runs on the engine's job threads, and WorkerCount is the number of its
        /// workers. Function pointers: native ones (an engine plugin's), or
        /// Marshal.GetFunctionPointerForDelegate of static NativeCallbacks.TaskEnqueueFn / TaskFinishFn
        /// delegates kept alive as long as the world. TaskUser is passed back to both.</summary>
        public IntPtr TaskEnqueueFn;
        public IntPtr TaskFinishFn;
        public IntPtr TaskUser;
        /// <summary>Agents' paths planned in one Step at most (at least 1): when many agents ask at once, the
        /// rest wait their turn (AgentState.Waiting), oldest first, so a step's cost stays bounded.</summary>
        public uint AgentPathsPerStep;

        public WorldOptions()
        {
            LibraryCheck.EnsureLoaded();
            AgentPathsPerStep = Native.nl_default_world_def().AgentPathsPerStep;
        }
    }

    /// <summary>
    /// A NavLink world (nl_world*): level geometry, navmeshes, links, path requests and agents. Every
    /// method may be called from several threads at once (navlink.h); Dispose waits for calls in flight.
    /// Failures throw NavLinkException with the status and the library's message.
    /// </summary>
    public sealed partial class World : IDisposable
    {
        private readonly WorldHandle handle = new WorldHandle();

        public World() : this(null) { }

        public unsafe World(WorldOptions options)
        {
            LibraryCheck.EnsureLoaded();
            options = options ?? new WorldOptions();
            WorldDef def = Native.nl_default_world_def();
            def.WorkerCount = options.WorkerCount;
            def.PathWorkerCount = options.PathWorkerCount;
            def.LogLevel = options.LogLevel;
            def.TaskEnqueueFn = options.TaskEnqueueFn;
            def.TaskFinishFn = options.TaskFinishFn;
            def.TaskUser = options.TaskUser;
            def.AgentPathsPerStep = options.AgentPathsPerStep;
            GCHandle log = default(GCHandle);
            if (options.Log != null)
            {
                log = GCHandle.Alloc(options.Log);
                def.LogFn = Trampolines.LogPointer;
                def.LogUser = GCHandle.ToIntPtr(log);
            }
            IntPtr world;
            StatusCode status = Native.nl_world_create(&def, &world);
            if (Status.Failed(status))
            {
                string message = Status.LastErrorMessage();
                if (log.IsAllocated) log.Free();
                throw new NavLinkException(status, message);
            }
            handle.Attach(world, log);
        }

        /// <summary>The loaded library's version (compare with the version this binding was written for).</summary>
        public static NavLinkVersion LibraryVersion
        {
            get
            {
                LibraryCheck.EnsureLoaded();
                return Native.nl_get_version();
            }
        }

        /// <summary>Threads used for batch work (1 when everything runs on the caller).</summary>
        public int WorkerCount
        {
            get { using (var w = Enter()) return Native.nl_world_get_worker_count(w.Pointer); }
        }

        /// <summary>The native pointer, for Native.* calls; valid until Dispose.</summary>
        public IntPtr DangerousGetPointer() { return handle.DangerousGetHandle(); }

        public bool IsDisposed { get { return handle.IsClosed; } }

        public void Dispose() { handle.Dispose(); }

        /// <summary>Raised when a callback (log, path finished) throws: exceptions never cross into
        /// native code. Without a handler the exception is written to stderr.</summary>
        public static event Action<Exception> CallbackException;

        internal static void ReportCallbackException(Exception e)
        {
            Action<Exception> handler = CallbackException;
            if (handler != null) handler(e);
            else Console.Error.WriteLine("NavLink: a callback threw: " + e);
        }

        private WorldLease Enter() { return new WorldLease(handle); }
    }
}
