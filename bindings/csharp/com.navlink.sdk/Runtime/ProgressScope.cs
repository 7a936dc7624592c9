using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // The (progress, user) pair of one long call (a link generation, a navmesh build): the static trampoline's
    // pointer and the handler as a GCHandle, freed when the call is over. Check turns the call's status into an
    // exception; an exception thrown by the handler wins over the CANCELLED it caused.
    internal struct ProgressScope : IDisposable
    {
        private readonly Trampolines.ProgressContext context;
        private GCHandle handle;
        public readonly IntPtr Function;
        public readonly IntPtr User;

        public ProgressScope(ProgressHandler progress)
        {
            context = null;
            handle = default(GCHandle);
            Function = IntPtr.Zero;
            User = IntPtr.Zero;
            if (progress == null) return;
            context = new Trampolines.ProgressContext { Handler = progress };
            handle = GCHandle.Alloc(context);
            Function = Trampolines.ProgressPointer;
            User = GCHandle.ToIntPtr(handle);
        }

        public void Check(StatusCode status)
        {
            string message = Status.LastErrorMessage();
            if (context != null && context.Error != null)
                throw new NavLinkException(status, "the progress callback threw: " + context.Error.Message, context.Error);
            if (Status.Failed(status)) throw new NavLinkException(status, message);
        }

        public void Dispose()
        {
            if (handle.IsAllocated) handle.Free();
        }
    }
}
