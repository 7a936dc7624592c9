using System;
using System.Threading;
using System.Threading.Tasks;

namespace NavLink
{
    /// <summary>
    /// A queued path request that owns its ticket (World.QueuePath). Finished is a Task that completes with
    /// the outcome when the request finishes (Cancelled too: when cancelled, released unfinished, or when the
    /// world goes); Wait blocks for it; Dispose releases the ticket (cancelling an unfinished request).
    /// <code>
    /// using (PathRequest request = world.QueuePath(query))
    /// {
    ///     PathOutcome outcome = await request.Finished;
    ///     PathResult result = request.GetResult();
    /// }
    /// </code>
    /// </summary>
    public sealed class PathRequest : IDisposable
    {
        // Continuations run on the thread pool, not inline on the NavLink thread that finished the request
        // (a path worker, or a host thread in ProcessPaths or Wait), which must get back to its queue.
        private readonly TaskCompletionSource<PathOutcome> finished =
            new TaskCompletionSource<PathOutcome>(TaskCreationOptions.RunContinuationsAsynchronously);
        // 1 once the ticket has been released: Dispose and the finalizer may race for it.
        private int released;

        internal PathRequest(World world) { World = world; }

        public World World { get; private set; }

        /// <summary>The raw ticket, for World's ticket methods; valid until Dispose.</summary>
        public PathTicket Ticket { get; internal set; }

        /// <summary>Completes with the outcome when the request finishes, on a thread pool thread.</summary>
        public Task<PathOutcome> Finished { get { return finished.Task; } }

        /// <summary>The outcome; PathOutcome.Pending while it runs.</summary>
        public PathOutcome Poll() { return World.PollPath(Ticket); }

        /// <summary>World.WaitPath: blocks until it has finished or the timeout has passed (null: as long as it
        /// takes) and returns the outcome, PathOutcome.Pending on a timeout.</summary>
        public PathOutcome Wait(TimeSpan? timeout = null) { return World.WaitPath(Ticket, timeout); }

        /// <summary>The result, or false while the request is pending.</summary>
        public bool TryGetResult(out PathResult result) { return World.TryGetPathResult(Ticket, out result); }

        /// <summary>The result, waiting for it as long as it takes.</summary>
        public PathResult GetResult()
        {
            PathResult result;
            while (!TryGetResult(out result)) Wait();
            return result;
        }

        public void Cancel() { World.CancelPath(Ticket); }

        /// <summary>Releases the ticket (an unfinished request is cancelled; Finished completes). Safe to call
        /// twice, and after the world's Dispose.</summary>
        public void Dispose()
        {
            Release();
            GC.SuppressFinalize(this);
        }

        // Only a finished request can get here: an unfinished one is held by its callback's GCHandle.
        ~PathRequest() { Release(); }

        internal void Complete(PathOutcome outcome) { finished.TrySetResult(outcome); }

        private void Release()
        {
            if (Interlocked.Exchange(ref released, 1) != 0 || Ticket.IsNull) return;
            World.ReleasePathIfAlive(Ticket);
        }
    }
}
