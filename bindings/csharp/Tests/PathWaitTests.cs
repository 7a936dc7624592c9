using System;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using NavLink;

namespace NavLink.Tests
{
    // Waiting for queued paths: World.WaitPath (nl_path_wait) with and without path workers, PathRequest's
    // Task completed from the native callback, its release by Dispose and by its finalizer.
    internal static class PathWaitTests
    {
        private static readonly TimeSpan Long = TimeSpan.FromSeconds(20);

        public static void Run(Checks check)
        {
            check.Run("path waits: with path workers", () =>
            {
                using (var world = new World())
                {
                    NavmeshId navmesh = PathTests.GapLevelWithLinks(world);
                    using (PathRequest request = world.QueuePath(Jumper(navmesh)))
                    {
                        check.That(request.Wait() == PathOutcome.Complete, "Wait() returns the outcome");
                        // The callback may still be running when the wait returns.
                        check.That(request.Finished.Wait(Long) && request.Finished.Result == PathOutcome.Complete,
                                   "the Task completes with the same outcome");
                        check.That(request.Wait(TimeSpan.Zero) == PathOutcome.Complete, "a finished request: timeout 0 says so");
                        PathResult result;
                        check.That(request.TryGetResult(out result) && result.Points.Any(p => p.Segment == LinkKind.Jump),
                                   "its result jumps the gap");
                    }
                    check.That(world.GetPathQueueStats().Unreleased == 0, "the using block released the ticket");
                }
            });

            check.Run("path waits: path_worker_count 0, the waiting thread plans", () =>
            {
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = PathTests.GapLevelWithLinks(world);
                    int here = Thread.CurrentThread.ManagedThreadId;
                    var callbackThreads = new int[2];
                    PathRequest walker = world.QueuePath(Walker(navmesh), (t, o) => callbackThreads[0] = Thread.CurrentThread.ManagedThreadId);
                    PathRequest jumper = world.QueuePath(Jumper(navmesh), (t, o) => callbackThreads[1] = Thread.CurrentThread.ManagedThreadId);
                    PathRequest later = world.QueuePath(Jumper(navmesh));

                    check.That(jumper.Wait(TimeSpan.Zero) == PathOutcome.Pending && world.GetPathQueueStats().Queued == 3,
                               "timeout 0 on a pending request: Pending, nothing planned");
                    unsafe
                    {
                        PathOutcome raw = PathOutcome.Complete;
                        StatusCode status = Native.nl_path_wait(world.DangerousGetPointer(), jumper.Ticket, 0, &raw);
                        check.That(status == StatusCode.InProgress && raw == PathOutcome.Pending,
                                   "raw nl_path_wait, timeout 0: " + status + ", " + raw);
                    }
                    check.That(!jumper.Finished.IsCompleted, "no Task completes before anything is planned");

                    check.That(jumper.Wait() == PathOutcome.Complete, "Wait() plans the queue up to the request");
                    check.That(walker.Poll() == PathOutcome.Partial && later.Poll() == PathOutcome.Pending,
                               "oldest first, and no further: walker " + walker.Poll() + ", later " + later.Poll());
                    check.That(callbackThreads[0] == here && callbackThreads[1] == here, "their callbacks ran on the waiting thread");
                    check.That(walker.Finished.IsCompleted && jumper.Finished.IsCompleted && !later.Finished.IsCompleted,
                               "the Tasks of the planned requests completed during the wait");

                    check.That(later.Wait(TimeSpan.FromMilliseconds(0.5)) == PathOutcome.Complete,
                               "a wait of 0.5 ms plans the one request (never split)");
                    foreach (PathRequest r in new[] { walker, jumper, later }) r.Dispose();
                    check.That(world.GetPathQueueStats().Unreleased == 0, "all released");

                    check.Throws(StatusCode.InvalidHandle, "nl_path_wait", () => world.WaitPath(later.Ticket), "waiting on a released ticket");
                    try
                    {
                        world.WaitPath(default(PathTicket), TimeSpan.FromMilliseconds(-2));
                        check.That(false, "a negative timeout is refused");
                    }
                    catch (ArgumentOutOfRangeException)
                    {
                        check.That(true, "a negative timeout is refused");
                    }
                }
            });

            check.Run("path waits: Tasks, Task.WhenAll and await", () =>
            {
                using (var world = new World())
                {
                    NavmeshId navmesh = PathTests.GapLevelWithLinks(world);
                    PathRequest[] requests = Enumerable.Range(0, 6)
                        .Select(i => world.QueuePath(i % 2 == 0 ? Jumper(navmesh) : Walker(navmesh))).ToArray();
                    Task<PathOutcome[]> all = Task.WhenAll(requests.Select(r => r.Finished));
                    check.That(all.Wait(Long), "Task.WhenAll of six requests completes");
                    check.That(all.Result.SequenceEqual(requests.Select((r, i) => i % 2 == 0 ? PathOutcome.Complete : PathOutcome.Partial)),
                               "their outcomes: " + string.Join(", ", all.Result));
                    check.That(requests.All(r => r.Poll() == r.Finished.Result), "polling agrees with the Tasks");
                    foreach (PathRequest r in requests) r.Dispose();

                    PathResult[] awaited = AwaitBoth(world, navmesh).GetAwaiter().GetResult();
                    check.That(awaited[0].Outcome == PathOutcome.Complete && awaited[0].LinksUsed == 1 &&
                               awaited[1].Outcome == PathOutcome.Partial, "await world.FindPathAsync: jumper and walker");
                    check.That(world.GetPathQueueStats().Unreleased == 0, "FindPathAsync released its tickets");
                }

                // Continuations run on the thread pool, not inline on the thread that ran the callback (here
                // the waiting thread, as there are no path workers), even when asked to run synchronously.
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = PathTests.GapLevelWithLinks(world);
                    using (PathRequest request = world.QueuePath(Jumper(navmesh)))
                    using (var continued = new ManualResetEventSlim())
                    {
                        int continuationThread = 0;
                        request.Finished.ContinueWith(t =>
                        {
                            continuationThread = Thread.CurrentThread.ManagedThreadId;
                            continued.Set();
                        }, TaskContinuationOptions.ExecuteSynchronously);
                        request.Wait();
                        check.That(continued.Wait(Long) && continuationThread != Thread.CurrentThread.ManagedThreadId,
                                   "the continuation ran on another thread than the callback's");
                    }
                }
            });

            check.Run("path waits: release by Dispose and by the finalizer", () =>
            {
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = PathTests.GapLevelWithLinks(world);
                    PathTicket ticket;
                    PathRequest pending;
                    using (pending = world.QueuePath(Jumper(navmesh)))
                        ticket = pending.Ticket;
                    check.That(pending.Finished.IsCompleted && pending.Finished.Result == PathOutcome.Cancelled,
                               "disposing a pending request cancels it and completes its Task");
                    check.Throws(StatusCode.InvalidHandle, "nl_path_poll", () => world.PollPath(ticket), "its ticket is released");
                    pending.Dispose();
                    check.That(world.GetPathQueueStats().Unreleased == 0, "a second Dispose is harmless");

                    // Dropped by a thread that has ended, so no stack holds them.
                    RunOnOtherThread(() => world.QueuePath(Jumper(navmesh)).Wait());
                    check.That(CollectUntil(() => world.GetPathQueueStats().Unreleased == 0),
                               "a finished request dropped without Dispose is released by its finalizer");
                    var dropped = new TaskCompletionSource<Task<PathOutcome>>();
                    RunOnOtherThread(() => dropped.SetResult(world.QueuePath(Jumper(navmesh)).Finished));
                    CollectUntil(() => false, 3);
                    PathQueueStats stats = world.GetPathQueueStats();
                    check.That(stats.Queued == 1 && stats.Unreleased == 1, "a pending request dropped is kept until it finishes");
                    world.ProcessPaths();
                    check.That(dropped.Task.Result.IsCompleted && dropped.Task.Result.Result == PathOutcome.Complete,
                               "it finishes and completes its Task");
                    check.That(CollectUntil(() => world.GetPathQueueStats().Unreleased == 0), "then its finalizer releases it");
                }

                PathRequest orphan;
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                    orphan = world.QueuePath(Jumper(PathTests.GapLevelWithLinks(world)));
                check.That(orphan.Finished.IsCompleted && orphan.Finished.Result == PathOutcome.Cancelled,
                           "disposing the world completes its requests' Tasks as Cancelled");
                orphan.Dispose();
                check.That(true, "disposing a request after its world is harmless");
            });

            check.Run("path waits: not from a path callback", () =>
            {
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = PathTests.GapLevelWithLinks(world);
                    PathRequest other = world.QueuePath(Jumper(navmesh));
                    StatusCode refused = 0;
                    string message = null;
                    using (world.QueuePath(Walker(navmesh), (t, o) =>
                    {
                        try
                        {
                            other.Wait(TimeSpan.Zero);
                        }
                        catch (NavLinkException e)
                        {
                            refused = e.StatusCode;
                            message = e.Message;
                        }
                    }))
                    {
                        world.ProcessPaths();
                    }
                    check.That(refused == (StatusCode.Failure | StatusCode.InvalidArgument) && message != null && message.Contains("callback"),
                               "a wait inside a callback: " + refused + ", '" + message + "'");
                    other.Dispose();
                }
            });
        }

        private static async Task<PathResult[]> AwaitBoth(World world, NavmeshId navmesh)
        {
            Task<PathResult> jumper = world.FindPathAsync(Jumper(navmesh));
            PathResult walker = await world.FindPathAsync(Walker(navmesh));
            return new[] { await jumper, walker };
        }

        private static void RunOnOtherThread(Action action)
        {
            var thread = new Thread(() => action());
            thread.Start();
            thread.Join();
        }

        // Finalizers run when the GC gets to them: a few rounds until done holds.
        private static bool CollectUntil(Func<bool> done, int rounds = 10)
        {
            for (int i = 0; i < rounds; ++i)
            {
                GC.Collect();
                GC.WaitForPendingFinalizers();
                if (done()) return true;
                Thread.Sleep(20);
            }
            return done();
        }

        private static PathQuery Jumper(NavmeshId navmesh)
        {
            return new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper());
        }

        private static PathQuery Walker(NavmeshId navmesh)
        {
            return new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker());
        }
    }
}
