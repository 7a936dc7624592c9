using System;
using System.Linq;
using System.Threading;
using NavLink;

namespace NavLink.Tests
{
    // Path requests on the gap level for two bodies: a walker (no jumps) cannot cross the gap, a jumper
    // must jump it. Synchronous (nl_path_find), queued with worker threads and callbacks, and queued
    // with no workers (nl_path_process, polling, cancelling).
    internal static class PathTests
    {
        public static void Run(Checks check)
        {
            check.Run("paths: walker and jumper (nl_path_find)", () =>
            {
                using (var world = new World())
                {
                    NavmeshId navmesh = GapLevelWithLinks(world);
                    PathResult jumper = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()));
                    CheckJumperAcross(check, world, jumper, "jumper");

                    PathResult walker = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker()));
                    CheckWalkerStopsAtGap(check, walker, "walker");

                    var noPartial = new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker()) { AcceptPartial = false };
                    PathResult none = world.FindPath(noPartial);
                    check.That(none.Outcome == PathOutcome.NoPath && none.Points.Length == 0,
                               "walker without accept_partial: " + none.Outcome + ", " + none.Points.Length + " points");

                    // A jumper whose jump is shorter than the gap is filtered out of every link.
                    AgentCapabilities shortJumper = TestLevels.Jumper();
                    shortJumper.MaxJumpDistance = 1.8f;
                    PathResult tooShort = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, shortJumper));
                    check.That(tooShort.Outcome == PathOutcome.Partial && tooShort.LinksUsed == 0,
                               "a 1.8 m jumper over a 2 m gap: " + tooShort.Outcome + ", " + tooShort.LinksUsed + " links");

                    PathResult stroll = world.FindPath(new PathQuery(navmesh, new Vec3(-9, 0, -3), new Vec3(-3, 0, 3), TestLevels.Walker()));
                    check.That(stroll.Outcome == PathOutcome.Complete && stroll.LinksUsed == 0 &&
                               stroll.Points.All(p => p.Segment == LinkKind.Walk) && stroll.Points.Length >= 2,
                               "a walk on one platform: " + stroll.Outcome + ", " + stroll.Points.Length + " points");
                    check.That(stroll.Length >= 8.48f && stroll.Length < 8.6f, "straight across the platform: " + stroll.Length + " m");

                    PathResult offStart = world.FindPath(new PathQuery(navmesh, new Vec3(0, -10, 30), TestLevels.EastPoint, TestLevels.Jumper()));
                    check.That(offStart.Outcome == PathOutcome.StartOffNavmesh, "a start far from the navmesh: " + offStart.Outcome);
                    PathResult offGoal = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, new Vec3(0, -10, 30), TestLevels.Jumper()));
                    check.That(offGoal.Outcome == PathOutcome.GoalOffNavmesh, "a goal far from the navmesh: " + offGoal.Outcome);
                }
            });

            check.Run("paths: why a path falls short (nl_path_explain)", () =>
            {
                using (var world = new World())
                {
                    // A platform 4.2 m above a floor, no stairs, no links: its top is an island of the navmesh.
                    TestLevels.AddBox(world, -10, -1, -10, 20, 0, 10);
                    TestLevels.AddBox(world, 0, 0, -3, 6, 4.2f, 3);
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
                    var down = new PathQuery(navmesh, new Vec3(3, 4.2f, 0), new Vec3(15, 0, 0), TestLevels.Walker()) { AcceptPartial = true };
                    PathShortfall stuck = world.ExplainPath(down);
                    check.That(stuck.Reason == PathShortfallReason.NoLinks && stuck.Limit == LinkLimit.None && stuck.Link.IsNull,
                               "off the platform without links: " + stuck.Reason + ", " + stuck.Limit);
                    check.That(stuck.Text.Contains("the navmesh has no links"), "the sentence: \"" + stuck.Text + "\"");
                    PathShortfall stroll = world.ExplainPath(new PathQuery(navmesh, new Vec3(15, 0, 0), new Vec3(18, 0, 0), TestLevels.Walker()));
                    check.That(stroll.Reason == PathShortfallReason.None && stroll.Text == "",
                               "a walk on the floor: " + stroll.Reason + ", \"" + stroll.Text + "\"");
                    unsafe
                    {
                        PathRequestDef def = Native.nl_default_path_request_def();
                        def.Navmesh = navmesh;
                        check.Status(Native.nl_path_explain(world.DangerousGetPointer(), &def, null), StatusCode.InvalidArgument,
                                     "out_shortfall", "nl_path_explain without out_shortfall");
                    }
                }
            });

            check.Run("paths: queued, with path workers and callbacks", () =>
            {
                using (var world = new World())
                {
                    NavmeshId navmesh = GapLevelWithLinks(world);
                    var outcomes = new PathOutcome[2];
                    var calls = new int[2];
                    using (var done = new CountdownEvent(2))
                    {
                        PathTicket walker = world.RequestPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker()),
                                                              (t, outcome) => { outcomes[0] = outcome; Interlocked.Increment(ref calls[0]); done.Signal(); });
                        PathTicket jumper = world.RequestPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()),
                                                              (t, outcome) => { outcomes[1] = outcome; Interlocked.Increment(ref calls[1]); done.Signal(); });
                        check.That(!walker.IsNull && !jumper.IsNull && !walker.Equals(jumper), "two distinct tickets");
                        check.That(done.Wait(TimeSpan.FromSeconds(20)), "both callbacks ran");
                        check.That(outcomes[0] == PathOutcome.Partial && outcomes[1] == PathOutcome.Complete,
                                   "callback outcomes: walker " + outcomes[0] + ", jumper " + outcomes[1]);
                        check.That(world.PollPath(walker) == outcomes[0] && world.PollPath(jumper) == outcomes[1], "poll agrees with the callbacks");

                        PathResult walked, jumped;
                        check.That(world.TryGetPathResult(walker, out walked) && world.TryGetPathResult(jumper, out jumped),
                                   "finished requests have results");
                        world.TryGetPathResult(walker, out walked);
                        world.TryGetPathResult(jumper, out jumped);
                        CheckWalkerStopsAtGap(check, walked, "queued walker");
                        CheckJumperAcross(check, world, jumped, "queued jumper");
                        PathResult direct = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()));
                        check.That(direct.Points.Select(p => p.Segment).SequenceEqual(jumped.Points.Select(p => p.Segment)),
                                   "queued and direct planning agree");

                        world.ReleasePath(walker);
                        world.ReleasePath(jumper);
                        check.Throws(StatusCode.InvalidHandle, "nl_path_poll", () => world.PollPath(walker), "polling a released ticket");
                        check.Throws(StatusCode.InvalidHandle, "nl_path_release", () => world.ReleasePath(jumper), "releasing twice");
                        Thread.Sleep(50);
                        check.That(calls[0] == 1 && calls[1] == 1, "each callback ran exactly once");
                    }
                    check.That(world.GetPathQueueStats().Unreleased == 0, "no tickets left");
                }
            });

            check.Run("paths: queued, run by the host (path_worker_count 0)", () =>
            {
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = GapLevelWithLinks(world);
                    int thread = Thread.CurrentThread.ManagedThreadId;
                    PathOutcome cancelledOutcome = PathOutcome.Pending;
                    int cancelledOnThread = -1;
                    PathTicket jumper = world.RequestPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()));
                    PathTicket doomed = world.RequestPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker()),
                                                          (t, outcome) => { cancelledOutcome = outcome; cancelledOnThread = Thread.CurrentThread.ManagedThreadId; });
                    PathQueueStats stats = world.GetPathQueueStats();
                    check.That(stats.Workers == 0 && stats.Queued == 2 && stats.Submitted == 2,
                               "queue: " + stats.Workers + " workers, " + stats.Queued + " queued, " + stats.Submitted + " submitted");
                    check.That(world.PollPath(jumper) == PathOutcome.Pending, "nothing runs before ProcessPaths");
                    PathResult early;
                    check.That(!world.TryGetPathResult(jumper, out early), "no result while pending (IN_PROGRESS)");

                    world.CancelPath(doomed);
                    check.That(cancelledOutcome == PathOutcome.Cancelled && cancelledOnThread == thread,
                               "a queued request cancels at once, its callback on the cancelling thread: " + cancelledOutcome);
                    check.Throws(StatusCode.InvalidArgument, "nl_path_process", () => world.ProcessPaths(0, double.NaN), "a NaN budget");
                    PathBudget small = World.DefaultPathBudget();
                    check.That(small.Size == (uint)System.Runtime.InteropServices.Marshal.SizeOf(typeof(PathBudget)) &&
                               small.MaxRequests == 0 && small.MaxMilliseconds == 0 && small.MaxSearchNodes == 0,
                               "the default budget: no limits");
                    small.Size = 8;
                    check.Throws(StatusCode.InvalidArgument, "budget", () => world.ProcessPaths(small), "a budget whose size is too small");
                    check.That(world.ProcessPaths() == 1, "ProcessPaths plans the one request left");
                    PathResult result;
                    check.That(world.TryGetPathResult(jumper, out result) && result.Outcome == PathOutcome.Complete, "planned by the host");
                    CheckJumperAcross(check, world, result, "host-run jumper");
                    stats = world.GetPathQueueStats();
                    check.That(stats.Finished == 2 && stats.Unreleased == 2 && stats.Queued == 0, "both finished, not released");

                    // A request still queued when the world goes: its callback reports it cancelled, once.
                    int lastCalls = 0;
                    PathOutcome last = PathOutcome.Pending;
                    world.RequestPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()),
                                      (t, outcome) => { last = outcome; ++lastCalls; });
                    world.Dispose();
                    check.That(lastCalls == 1 && last == PathOutcome.Cancelled, "destroying the world cancels what is queued: " + last);
                }
            });

            check.Run("paths: budgets and finished requests taken by the host (TakeFinishedPaths)", () =>
            {
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = GapLevelWithLinks(world);
                    var jumperQuery = new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper());
                    var walkerQuery = new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker());
                    check.That(world.TakeFinishedPaths().Length == 0, "nothing finished yet");

                    // Budgets: a request is never split, so each limit lets one request through.
                    PathTicket a = world.RequestPath(jumperQuery), b = world.RequestPath(walkerQuery);
                    check.That(world.ProcessPaths(maxRequests: 1) == 1 && world.PollPath(a) == PathOutcome.Complete &&
                               world.PollPath(b) == PathOutcome.Pending, "maxRequests 1 plans the first request only");
                    PathTicket c = world.RequestPath(jumperQuery), d = world.RequestPath(walkerQuery);
                    PathTicket e = world.RequestPath(jumperQuery);
                    check.That(world.ProcessPaths(maxSearchNodes: 1) == 1 && world.PollPath(b) == PathOutcome.Partial &&
                               world.PollPath(c) == PathOutcome.Pending, "maxSearchNodes 1: the request that crosses the limit");
                    PathBudget oneNode = World.DefaultPathBudget();
                    oneNode.MaxSearchNodes = 1;
                    check.That(world.ProcessPaths(oneNode) == 1 && world.PollPath(d) == PathOutcome.Pending,
                               "a PathBudget with MaxSearchNodes 1: one request");
                    check.That(world.ProcessPaths(maxMilliseconds: 1e-6) == 1 && world.PollPath(e) == PathOutcome.Pending,
                               "a budget of 1 ns: one request");
                    check.That(world.ProcessPaths() == 1, "no limits: the rest");

                    // Each finished request once, oldest first, with its outcome.
                    FinishedPath[] finished = world.TakeFinishedPaths();
                    var expected = new[] { new FinishedPath(a, PathOutcome.Complete), new FinishedPath(b, PathOutcome.Partial),
                                           new FinishedPath(c, PathOutcome.Complete), new FinishedPath(d, PathOutcome.Partial),
                                           new FinishedPath(e, PathOutcome.Complete) };
                    check.That(finished.SequenceEqual(expected), "taken: " + string.Join(", ", finished));
                    check.That(world.TakeFinishedPaths().Length == 0, "each is taken once");

                    // Released tickets are not reported, finished or cancelled; cancelled ones are.
                    int calls = 0;
                    PathTicket released = world.RequestPath(jumperQuery, (t, o) => ++calls);
                    PathTicket cancelled = world.RequestPath(walkerQuery);
                    PathTicket kept = world.RequestPath(jumperQuery);
                    PathTicket releasedLater = world.RequestPath(walkerQuery);
                    world.ReleasePath(released);
                    world.CancelPath(cancelled);
                    check.That(world.ProcessPaths() == 2 && calls == 1, "two left to plan; the released request called back once");
                    world.ReleasePath(releasedLater);
                    finished = world.TakeFinishedPaths();
                    expected = new[] { new FinishedPath(cancelled, PathOutcome.Cancelled), new FinishedPath(kept, PathOutcome.Complete) };
                    check.That(finished.SequenceEqual(expected), "taken after releases: " + string.Join(", ", finished));

                    // More than the binding takes in one call (16) come back in one array.
                    var many = Enumerable.Range(0, 40).Select(i => world.RequestPath(i % 2 == 0 ? jumperQuery : walkerQuery)).ToArray();
                    check.That(world.ProcessPaths() == 40, "40 planned");
                    finished = world.TakeFinishedPaths();
                    check.That(finished.Select(f => f.Ticket).SequenceEqual(many) &&
                               finished.All(f => f.Outcome == (Array.IndexOf(many, f.Ticket) % 2 == 0 ? PathOutcome.Complete : PathOutcome.Partial)),
                               "40 finished requests taken in order: " + finished.Length);

                    // The raw call: the library reads the element size from out_finished[0].size.
                    PathTicket raw = world.RequestPath(jumperQuery);
                    world.ProcessPaths();
                    unsafe
                    {
                        var buffer = new PathFinished[2];
                        uint count = 99, remaining = 99;
                        fixed (PathFinished* f = buffer)
                        {
                            check.Status(Native.nl_path_take_finished(world.DangerousGetPointer(), f, 2, &count, &remaining),
                                         StatusCode.InvalidArgument, "out_finished", "an element size left at 0");
                            buffer[0] = Native.nl_path_finished_init();
                            StatusCode status = Native.nl_path_take_finished(world.DangerousGetPointer(), f, 2, &count, &remaining);
                            check.That(status == StatusCode.Success && count == 1 && remaining == 0 && buffer[0].Ticket.Equals(raw) &&
                                       buffer[0].Outcome == PathOutcome.Complete && buffer[0].User == IntPtr.Zero,
                                       "a refused take loses nothing: " + count + " taken");
                        }
                    }
                }
            });

            check.Run("paths: invalid requests", () =>
            {
                using (var world = new World(new WorldOptions { PathWorkerCount = 0 }))
                {
                    NavmeshId navmesh = GapLevelWithLinks(world);
                    int calls = 0;
                    check.Throws(StatusCode.InvalidHandle, "nl_path_request",
                                 () => world.RequestPath(new PathQuery(default(NavmeshId), TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Walker()),
                                                         (t, o) => ++calls), "a request on the null navmesh");
                    AgentCapabilities negative = TestLevels.Jumper();
                    negative.MaxJumpDistance = -1;
                    check.Throws(StatusCode.InvalidArgument, "max_jump_distance",
                                 () => world.RequestPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, negative), (t, o) => ++calls),
                                 "a negative jump distance");
                    check.Throws(StatusCode.InvalidArgument, "start",
                                 () => world.FindPath(new PathQuery(navmesh, new Vec3(float.NaN, 0, 0), TestLevels.EastPoint, TestLevels.Walker())),
                                 "a NaN start");
                    world.ProcessPaths();
                    check.That(calls == 0 && world.GetPathQueueStats().Submitted == 0, "refused requests never call back");
                    check.Throws(StatusCode.InvalidHandle, "nl_path_cancel", () => world.CancelPath(default(PathTicket)), "cancelling the null ticket");
                    unsafe
                    {
                        check.Status(Native.nl_path_get_queue_stats(world.DangerousGetPointer(), null), StatusCode.InvalidArgument,
                                     "out_stats", "nl_path_get_queue_stats without out_stats");
                    }
                }
            });
        }

        internal static NavmeshId GapLevelWithLinks(World world)
        {
            TestLevels.AddGapLevel(world);
            NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
            world.GenerateLinks(navmesh);
            return navmesh;
        }

        // Across the gap in one jump: walk to the west rim, jump (a generated jump link, apex above), walk to the goal.
        private static void CheckJumperAcross(Checks check, World world, PathResult r, string who)
        {
            if (!check.That(r.Outcome == PathOutcome.Complete, who + ": outcome " + r.Outcome)) return;
            PathPoint[] p = r.Points;
            int[] jumps = Enumerable.Range(0, p.Length).Where(i => p[i].Segment != LinkKind.Walk).ToArray();
            if (!check.That(jumps.Length == 1 && p[jumps[0]].Segment == LinkKind.Jump && r.LinksUsed == 1,
                            who + ": exactly one jump segment (" + jumps.Length + " link segments, links_used " + r.LinksUsed + ")")) return;
            int j = jumps[0];
            check.That(j + 1 < p.Length && p[j].Position.X < -1 && p[j + 1].Position.X > 1,
                       who + ": the jump goes from the west rim to the east one");
            Link link;
            check.That(world.TryGetLink(p[j].Link, out link) && link.Kind == LinkKind.Jump && link.Generated == 1,
                       who + ": the jump names a generated jump link");
            check.That(p[j].Apex.Y > Math.Max(p[j].Position.Y, p[j + 1].Position.Y), who + ": the apex is above both ends");
            check.That(p[p.Length - 1].Segment == LinkKind.Walk && p[0].Link.IsNull, who + ": walks elsewhere");
            check.That(p[0].Position.HorizontalDistance(TestLevels.WestPoint) < 0.01f &&
                       p[p.Length - 1].Position.HorizontalDistance(TestLevels.EastPoint) < 0.01f,
                       who + ": from the start " + p[0].Position + " to the goal " + p[p.Length - 1].Position);
            check.That(r.Length >= 12f && r.Length < 13f, who + ": " + r.Length + " m");
        }

        // No link for a walker: the path leads to the reachable point nearest the goal, the west rim.
        private static void CheckWalkerStopsAtGap(Checks check, PathResult r, string who)
        {
            check.That(r.Outcome == PathOutcome.Partial, who + ": outcome " + r.Outcome);
            check.That(r.LinksUsed == 0 && r.Points.All(q => q.Segment == LinkKind.Walk && q.Link.IsNull), who + ": walks only");
            check.That(r.Points.Length >= 2 && r.Points.All(q => q.Position.X < -1), who + ": stays on the west platform");
            check.That(r.Points.Length >= 2 && r.Points[r.Points.Length - 1].Position.X > -2.1f,
                       who + ": ends at the west rim, nearest the goal");
        }
    }
}
