using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // Owns an nl_world*. SafeHandle counts the calls in flight (World.Enter): the handle is released
    // (nl_world_destroy) only after the last one returns, which is exactly the rule of navlink.h:
    // nl_world_destroy must not overlap any other call on the world.
    internal sealed class WorldHandle : SafeHandle
    {
        // The log callback's context; freed after the world, the last thing that could call the callback.
        private GCHandle logContext;

        public WorldHandle() : base(IntPtr.Zero, true) { }

        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }

        internal void Attach(IntPtr world, GCHandle log)
        {
            SetHandle(world);
            logContext = log;
        }

        protected override bool ReleaseHandle()
        {
            // Pending path requests finish here (cancelled), their callbacks run on this thread.
            Native.nl_world_destroy(handle);
            if (logContext.IsAllocated) logContext.Free();
            return true;
        }
    }

    /// <summary>Holds a reference on the world handle for the duration of one native call.</summary>
    internal struct WorldLease : IDisposable
    {
        private readonly WorldHandle owner;
        public readonly IntPtr Pointer;

        internal WorldLease(WorldHandle handle)
        {
            bool added = false;
            if (handle.IsClosed) throw new ObjectDisposedException("World");
            handle.DangerousAddRef(ref added);
            owner = handle;
            Pointer = handle.DangerousGetHandle();
        }

        public void Dispose() { owner.DangerousRelease(); }
    }
}
