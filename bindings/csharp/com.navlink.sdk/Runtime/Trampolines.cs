using System;
using System.Runtime.InteropServices;
using AOT;

namespace NavLink
{
    /// <summary>Receives a log line from a world: level (LogLevel), status, message.</summary>
    public delegate void LogHandler(LogLevel level, StatusCode status, string message);

    /// <summary>Progress of a link generation or a navmesh build: return false to cancel it.</summary>
    public delegate bool ProgressHandler(float fraction, string stage);

    /// <summary>Called once when a queued path request finishes, on the thread that finished it.</summary>
    public delegate void PathFinishedHandler(PathTicket ticket, PathOutcome outcome);

    // The static functions native code calls back, one per callback type, as IL2CPP requires: static,
    // non-generic, marked [MonoPInvokeCallback], the managed target found through the `user` pointer (a
    // GCHandle). Exceptions never cross into native code: they are caught here and handed on.
    internal static class Trampolines
    {
        // Kept in static fields: the delegates, hence the function pointers, live as long as the program.
        private static readonly NativeCallbacks.LogFn LogDelegate = Log;
        private static readonly NativeCallbacks.ProgressFn ProgressDelegate = Progress;
        private static readonly NativeCallbacks.PathCallback PathDelegate = PathFinished;

        internal static readonly IntPtr LogPointer = Marshal.GetFunctionPointerForDelegate(LogDelegate);
        internal static readonly IntPtr ProgressPointer = Marshal.GetFunctionPointerForDelegate(ProgressDelegate);
        internal static readonly IntPtr PathPointer = Marshal.GetFunctionPointerForDelegate(PathDelegate);

        [MonoPInvokeCallback(typeof(NativeCallbacks.LogFn))]
        private static void Log(IntPtr user, LogLevel level, StatusCode status, IntPtr message)
        {
            try
            {
                var handler = (LogHandler)GCHandle.FromIntPtr(user).Target;
                handler(level, status, Utf8.Decode(message));
            }
            catch (Exception e)
            {
                World.ReportCallbackException(e);
            }
        }

        /// <summary>The context of one call's progress callback: the handler, and what it threw.</summary>
        internal sealed class ProgressContext
        {
            public ProgressHandler Handler;
            public Exception Error;
        }

        [MonoPInvokeCallback(typeof(NativeCallbacks.ProgressFn))]
        private static int Progress(IntPtr user, float fraction, IntPtr stage)
        {
            var context = (ProgressContext)GCHandle.FromIntPtr(user).Target;
            try
            {
                return context.Handler(fraction, Utf8.Decode(stage)) ? 1 : 0;
            }
            catch (Exception e)
            {
                // Cancel the call; World rethrows this once the native call has returned.
                context.Error = e;
                return 0;
            }
        }

        [MonoPInvokeCallback(typeof(NativeCallbacks.PathCallback))]
        private static void PathFinished(IntPtr user, PathTicket ticket, PathOutcome outcome)
        {
            // navlink.h: called exactly once per accepted request, so the context is freed here.
            GCHandle context = GCHandle.FromIntPtr(user);
            var handler = (PathFinishedHandler)context.Target;
            context.Free();
            try
            {
                handler(ticket, outcome);
            }
            catch (Exception e)
            {
                World.ReportCallbackException(e);
            }
        }
    }
}
