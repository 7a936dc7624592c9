using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;
using NavLink;

namespace NavLink.Tests
{
    // Agents on the bridge level (tests/abi/agents_tests.c's): a jumper takes a generated jump across the gap
    // while a walker goes round by the bridge, as the states read in bulk and the step's events say; the
    // trajectory of the jump mid-flight; bad input refused. And a ferry (tests/core/world/surface_tests.cpp's): walkers
    // wait at a gangway for a shuttle, ride it across a chasm and get off on the far side, AgentInfo saying which
    // navmesh and carrier they stand on.
    internal static class AgentTests
    {
        private const float Dt = 1.0f / 30.0f;
        private const int MaxSteps = 30 * 20;

        // The ferry: two 6 x 6 m ledges (boxes x in [0, 6] and [16, 22], z in [0, 6], tops y = 0) with one static
        // navmesh of their tops eroded 0.3 m (one quad each), and a 4 x 4 m movable box (top y = 0 in its own space,
        // x and z in [-2, 2]) carrying its top eroded 0.3 m, on a timetable: docked at the near ledge (centre x = 8)
        // for 3 s, 4 s across, docked at the far one (x = 14) for 3 s, 4 s back.
        private static readonly float[] FerryLedges = {0.3f, 0, 0.3f, 0.3f, 0, 5.7f, 5.7f, 0, 5.7f, 5.7f, 0, 0.3f,
                                                       16.3f, 0, 0.3f, 16.3f, 0, 5.7f, 21.7f, 0, 5.7f, 21.7f, 0, 0.3f};
        private static readonly float[] ShuttleTop = {-1.7f, 0, -1.7f, -1.7f, 0, 1.7f, 1.7f, 0, 1.7f, 1.7f, 0, -1.7f};
        private const float NearDock = 8, FarDock = 14;
        private static readonly Vec3 FerryGoal = new Vec3(20, 0, 3);

        /// <summary>The shuttle's transform: its centre at (x, 0, 3) (column-major).</summary>
        private static float[] ShuttleAt(float x) { return new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 3, 1}; }

        /// <summary>The shuttle's centre x at time t of its 14 s timetable.</summary>
        private static float ShuttleX(double t)
        {
            double u = t % 14.0;
            if (u < 3) return NearDock;
            if (u < 7) return (float)(NearDock + (FarDock - NearDock) * (u - 3) / 4);
            if (u < 10) return FarDock;
            return (float)(FarDock - (FarDock - NearDock) * (u - 10) / 4);
        }

        private static float Distance(Vec3 a, Vec3 b)
        {
            float x = a.X - b.X, y = a.Y - b.Y, z = a.Z - b.Z;
            return (float)Math.Sqrt(x * x + y * y + z * z);
        }

        public static void Run(Checks check)
        {
            check.Run("agents: a walker goes round, a jumper jumps", () =>
            {
                AgentDef defaults = World.DefaultAgentDef();
                check.That(defaults.Size == (uint)Marshal.SizeOf(typeof(AgentDef)) && defaults.Height == 2 && defaults.MaxSpeed == 3.5f &&
                           defaults.MaxAcceleration == 8 && Math.Abs(defaults.Gravity - 9.81f) < 1e-6f && defaults.Avoidance == 1 &&
                           defaults.Capabilities.Radius == 0.6f && defaults.Navmesh.IsNull && defaults.TakeoffSpeed == 0 &&
                           defaults.GiveUpSeconds == 0,
                           "the default agent def");
                check.That((uint)AgentEventKind.Waiting == 7u && (uint)AgentReason.Crowd == 8u,
                           "waiting for room: AgentEventKind.Waiting " + (uint)AgentEventKind.Waiting + ", AgentReason.Crowd " +
                           (uint)AgentReason.Crowd);
                check.That(new WorldOptions().AgentPathsPerStep == 32, "32 agent paths per step by default");

                using (var world = new World())
                {
                    NavmeshId navmesh = TestLevels.AddBridgeLevel(world);
                    check.That(world.GetLinks(navmesh).Any(l => l.Kind == LinkKind.Jump), "jump links across the gap");
                    AgentId walker = AddAgent(world, navmesh, 1, 2, 0, 11), jumper = AddAgent(world, navmesh, 1, 3, 3, 22);
                    check.That(!walker.Equals(jumper) && world.IsValid(walker) && world.GetAgentInfo(walker).State == AgentState.Idle,
                               "two agents, standing");
                    var jumperStates = new List<AgentState> {world.GetAgentInfo(jumper).State};
                    world.SetAgentDestination(walker, new Vec3(9, 0, 2));
                    world.SetAgentDestination(jumper, new Vec3(9, 0, 3));
                    jumperStates.Add(world.GetAgentInfo(jumper).State);

                    var events = new List<AgentEvent>();
                    PathPoint[] walkerCorners = null, jumperCorners = null;
                    AgentTrajectory trajectory = default(AgentTrajectory);
                    AgentInfo inFlight = default(AgentInfo);
                    bool twoAgentsListed = true, sawTrajectory = false;
                    float walkerMaxZ = 0;
                    for (int step = 0; step < MaxSteps && events.Count(e => e.Kind == AgentEventKind.Arrived) < 2; ++step)
                    {
                        world.Step(Dt);
                        AgentEvent[] stepEvents = world.GetAgentEvents();
                        events.AddRange(stepEvents);
                        if (stepEvents.Any(e => e.Kind == AgentEventKind.PathReady))
                        {
                            walkerCorners = world.GetAgentCorners(walker);
                            jumperCorners = world.GetAgentCorners(jumper);
                        }
                        AgentInfo[] infos = world.GetAgents();
                        twoAgentsListed &= infos.Length == 2;
                        foreach (AgentInfo info in infos)
                        {
                            if (info.Id.Equals(walker)) walkerMaxZ = Math.Max(walkerMaxZ, info.Position.Z);
                            if (!info.Id.Equals(jumper)) continue;
                            if (info.State != jumperStates.Last()) jumperStates.Add(info.State);
                            if (info.State == AgentState.Jumping && !sawTrajectory)
                                sawTrajectory = world.TryGetAgentTrajectory(jumper, out trajectory);
                            if (info.State == AgentState.Jumping) inFlight = info;
                        }
                    }

                    check.That(twoAgentsListed, "GetAgents lists both agents after every step");
                    check.That(events.All(e => e.Size == (uint)Marshal.SizeOf(typeof(AgentEvent)) &&
                                               e.UserData == (e.Agent.Equals(walker) ? 11u : 22u)),
                               "each event has its size and its agent's user data");
                    AgentEvent[] ready = events.Where(e => e.Kind == AgentEventKind.PathReady).ToArray();
                    check.That(ready.Length == 2 && ready.All(e => e.Reason == AgentReason.DestinationSet),
                               ready.Length + " paths ready, planned for the destinations set");
                    check.That(events.Count(e => e.Kind == AgentEventKind.Arrived) == 2, "both arrived");
                    check.That(world.GetAgentInfo(walker).State == AgentState.Arrived && world.GetAgentInfo(jumper).State == AgentState.Arrived,
                               "both in AgentState.Arrived");

                    check.That(!events.Any(e => e.Agent.Equals(walker) && e.Kind == AgentEventKind.LinkStarted) && walkerMaxZ > 8,
                               "the walker takes no link and goes round by the bridge (z up to " + walkerMaxZ + ")");
                    check.That(walkerCorners != null && walkerCorners.Length >= 2 && walkerCorners.All(p => p.Segment == LinkKind.Walk),
                               "the walker's corners: a walk");
                    check.That(jumperCorners != null && jumperCorners.Count(p => p.Segment == LinkKind.Jump) == 1,
                               "the jumper's corners: one jump");

                    AgentEvent[] started = events.Where(e => e.Agent.Equals(jumper) && e.Kind == AgentEventKind.LinkStarted).ToArray();
                    AgentEvent[] finished = events.Where(e => e.Agent.Equals(jumper) && e.Kind == AgentEventKind.LinkFinished).ToArray();
                    check.That(started.Length == 1 && finished.Length == 1 && started[0].Link.Equals(finished[0].Link),
                               "the jumper starts and finishes one link: " + started.Length + " started, " + finished.Length + " finished");
                    if (started.Length == 1)
                    {
                        Link jump = world.GetLink(started[0].Link);
                        check.That(jump.Kind == LinkKind.Jump && jump.Generated == 1, "the jumper's link is a generated jump");
                    }
                    var expected = new[] {AgentState.Idle, AgentState.Waiting, AgentState.Walking, AgentState.Jumping, AgentState.Walking,
                                          AgentState.Arrived};
                    check.That(IsSubsequence(expected, jumperStates),
                               "the jumper's states: " + string.Join(" ", jumperStates));

                    check.That(sawTrajectory, "the trajectory of the jump in the air");
                    check.That(trajectory.Kind == TrajectoryKind.Arc && trajectory.Duration > 0 && trajectory.Elapsed >= 0 &&
                               trajectory.Elapsed <= trajectory.Duration && trajectory.Link.Equals(started.FirstOrDefault().Link),
                               "an arc of " + trajectory.Duration + " s on the jumper's link, " + trajectory.Elapsed + " s in");
                    check.That(trajectory.Apex.Y > Math.Max(trajectory.From.Y, trajectory.To.Y) &&
                               trajectory.Point(0).Equals(trajectory.From) && trajectory.Point(3).Equals(trajectory.To),
                               "the apex above both ends; an arc's points are its ends");
                    check.That(inFlight.Link.Equals(trajectory.Link) && inFlight.LinkProgress >= 0 && inFlight.LinkProgress <= 1,
                               "in the air, AgentInfo names the link and its progress: " + inFlight.LinkProgress);

                    AgentTrajectory none;
                    check.That(!world.TryGetAgentTrajectory(jumper, out none), "no trajectory on the ground");
                    check.That(world.GetAgentCorners(walker).Length <= 1, "an arrived agent has no corners left");
                }
            });

            check.Run("agents: a ferry carries walkers across a chasm", () =>
            {
                using (var world = new World())
                {
                    TestLevels.AddBox(world, 0, -1, 0, 6, 0, 6);
                    TestLevels.AddBox(world, 16, -1, 0, 22, 0, 6);
                    MeshId shuttle = TestLevels.AddBox(world, -2, -0.5f, -2, 2, 0, 2, MeshFlags.Movable, ShuttleAt(FarDock));
                    AgentType body = World.DefaultAgentType();
                    body.Radius = 0.3f;
                    NavmeshId ledges = world.AddNavmesh(new NavmeshInput
                    {
                        Vertices = FerryLedges, Indices = new uint[] {0, 1, 2, 3, 4, 5, 6, 7}, PolygonVertexCounts = new byte[] {4, 4},
                        AgentType = body,
                    });
                    NavmeshId deck = world.AddNavmesh(new NavmeshInput
                    {
                        Vertices = ShuttleTop, Indices = new uint[] {0, 1, 2, 3}, PolygonVertexCounts = new byte[] {4}, AgentType = body,
                        Carrier = shuttle,
                    });
                    // The gangways: manual cross links whose requirements are taken as given (all zero: a gap of 0,
                    // walked, not jumped), each placed while the shuttle stands at its dock.
                    Func<NavmeshId, Vec3, NavmeshId, Vec3, LinkId> gangway = (navmesh, start, landing, end) =>
                    {
                        LinkDef def = World.DefaultLinkDef();
                        def.Start = start;
                        def.End = end;
                        def.LandingNavmesh = landing;
                        def.RequirementsAsGiven = 1;
                        return world.AddLink(navmesh, def);
                    };
                    LinkId leave = gangway(deck, new Vec3(15.4f, 0, 3), ledges, new Vec3(16.6f, 0, 3));
                    world.SetMeshTransform(shuttle, ShuttleAt(NearDock));
                    LinkId board = gangway(ledges, new Vec3(5.6f, 0, 3), deck, new Vec3(6.6f, 0, 3));
                    Link boardLink = world.GetLink(board);
                    check.That(boardLink.Kind == LinkKind.Manual && boardLink.Requirements.Gap == 0 && boardLink.Holds == 1 &&
                               world.GetLink(leave).Holds == 0, "the gangways: manual, no gap; the one at the shuttle's dock holds");

                    var walkers = new List<AgentId>();
                    foreach (float z in new[] {2f, 4f})
                    {
                        AgentDef def = World.DefaultAgentDef();
                        def.Navmesh = ledges;
                        def.Position = new Vec3(2, 0, z);
                        def.Capabilities.Radius = 0.3f;
                        walkers.Add(world.AddAgent(def));
                        world.SetAgentDestination(walkers.Last(), FerryGoal);
                    }
                    AgentInfo first = world.GetAgentInfo(walkers[0]);
                    check.That(first.Navmesh.Equals(ledges) && first.Carrier.IsNull && first.CarrierPosition.Equals(first.Position),
                               "standing on the near ledge, on no carrier: " + first.Navmesh + " " + first.Carrier);

                    var arrivedInfo = new Dictionary<AgentId, AgentInfo>();
                    var taken = new List<KeyValuePair<AgentId, LinkId>>();
                    var failures = new List<string>();
                    int waited = 0, riding = 0;
                    double t = 4.0;  // the shuttle has just left: the first to reach the gangway waits for it
                    for (int step = 0; step < 90 * 30 && arrivedInfo.Count < walkers.Count; ++step)
                    {
                        t += Dt;
                        float x = ShuttleX(t);
                        world.SetMeshTransform(shuttle, ShuttleAt(x));
                        world.Step(Dt);
                        AgentEvent[] events = world.GetAgentEvents();
                        foreach (AgentEvent e in events)
                        {
                            if (e.Kind == AgentEventKind.LinkStarted) taken.Add(new KeyValuePair<AgentId, LinkId>(e.Agent, e.Link));
                            if (e.Kind == AgentEventKind.Failed) failures.Add("t " + t + ": an agent failed, reason " + e.Reason);
                            if (e.Kind == AgentEventKind.Arrived) arrivedInfo[e.Agent] = world.GetAgentInfo(e.Agent);
                        }
                        foreach (AgentInfo info in world.GetAgents())
                        {
                            if (info.State == AgentState.Waiting && info.Link.Equals(board)) ++waited;
                            string where = "t " + t + ", shuttle at x " + x + ": " + info.State + " on " + info.Navmesh + ", carrier " +
                                           info.Carrier + ", at " + info.Position + ", in its space " + info.CarrierPosition;
                            if (!info.Navmesh.Equals(ledges) && !info.Navmesh.Equals(deck))
                                failures.Add(where + ": on neither navmesh");
                            else if (info.State == AgentState.Jumping || info.State == AgentState.Falling || info.State == AgentState.Traversing)
                            {
                                // In the air over a cross link (both gangways are): flown in the world.
                                if (Distance(info.CarrierPosition, info.Position) > 1e-3f) failures.Add(where + ": in the air");
                            }
                            else if (info.Navmesh.Equals(deck))
                            {
                                // On the deck: riding the shuttle, whose centre is at (x, 0, 3), unturned.
                                ++riding;
                                if (!info.Carrier.Equals(shuttle) ||
                                    Distance(info.CarrierPosition, new Vec3(info.Position.X - x, info.Position.Y, info.Position.Z - 3)) > 1e-3f)
                                    failures.Add(where + ": on the deck");
                            }
                            else if (!info.Carrier.IsNull || Distance(info.CarrierPosition, info.Position) > 1e-3f)
                                failures.Add(where + ": on a ledge");
                        }
                    }

                    check.That(failures.Count == 0, failures.Count + " bad steps; the first: " + failures.FirstOrDefault());
                    check.That(arrivedInfo.Count == walkers.Count, arrivedInfo.Count + " of " + walkers.Count + " arrived by t = " + t + " s");
                    check.That(waited > 0, "an agent waited at the gangway for the shuttle (Waiting, Link the gangway): " + waited + " agent steps");
                    check.That(riding > 0, "an agent stood on the shuttle's deck (Navmesh, Carrier, CarrierPosition): " + riding + " agent steps");
                    foreach (AgentId walker in walkers)
                    {
                        check.That(taken.Contains(new KeyValuePair<AgentId, LinkId>(walker, board)) &&
                                   taken.Contains(new KeyValuePair<AgentId, LinkId>(walker, leave)),
                                   walker + " boarded by the near gangway and got off by the far one");
                        AgentInfo arrived;
                        if (!check.That(arrivedInfo.TryGetValue(walker, out arrived), walker + " arrived")) continue;
                        check.That(arrived.Navmesh.Equals(ledges) && arrived.Carrier.IsNull && arrived.State == AgentState.Arrived,
                                   "at arrival on the ledges' navmesh, on no carrier: " + arrived.Navmesh + " " + arrived.Carrier);
                        // Two bodies share the goal: they stand round it.
                        check.That(arrived.Position.HorizontalDistance(FerryGoal) < 1.5f,
                                   "at the goal: " + arrived.Position);
                    }
                }
            });

            check.Run("agents: bad input", () =>
            {
                check.Throws(StatusCode.InvalidArgument, "agent_paths_per_step", () => new World(new WorldOptions { AgentPathsPerStep = 0 }),
                             "a world that plans no agent paths");
                using (var world = new World(new WorldOptions { WorkerCount = 1, AgentPathsPerStep = 1 }))
                {
                    NavmeshId navmesh = TestLevels.AddBridgeLevel(world);
                    AgentId agent = AddAgent(world, navmesh, 1, 2, 0, 0);
                    AgentDef off = World.DefaultAgentDef();
                    off.Navmesh = navmesh;
                    off.Position = new Vec3(5, 0, 2);  // over the gap
                    check.Throws(StatusCode.NotFound, "def->position is not on the navmesh", () => world.AddAgent(off), "an agent off the navmesh");
                    check.Throws(StatusCode.NotFound, "nearest navmesh point", () => world.SetAgentDestination(agent, new Vec3(5, 0, 2)),
                                 "a destination off the navmesh");
                    check.That(world.GetAgentInfo(agent).HasDestination == 0, "a refused destination is not kept");
                    check.Throws(StatusCode.InvalidArgument, "point", () => world.SetAgentDestination(agent, new Vec3(float.NaN, 0, 0)),
                                 "a NaN destination");
                    check.Throws(StatusCode.InvalidArgument, "dt", () => world.Step(float.NaN), "a NaN step");
                    check.Throws(StatusCode.InvalidArgument, "max_speed", () => world.SetAgentSpeed(agent, -1, 1), "a negative speed");
                    AgentCapabilities nanRadius = TestLevels.Walker();
                    nanRadius.Radius = float.NaN;
                    check.Throws(StatusCode.InvalidArgument, "radius", () => world.SetAgentCapabilities(agent, nanRadius), "a NaN radius");

                    // A raw call must set the element size of its output array, as in C.
                    var infos = new AgentInfo[1];
                    uint count;
                    unsafe
                    {
                        fixed (AgentInfo* p = infos)
                            check.Status(Native.nl_world_get_agents(world.DangerousGetPointer(), p, 1, &count),
                                         StatusCode.InvalidArgument, "size", "a raw list with an unset element size");
                    }

                    // Its navmesh removed: the agent fails, with its event.
                    world.SetAgentDestination(agent, new Vec3(3, 0, 5));
                    world.Step(0.1f);
                    world.RemoveNavmesh(navmesh);
                    world.Step(0.1f);
                    AgentEvent[] events = world.GetAgentEvents();
                    check.That(events.Length == 1 && events[0].Kind == AgentEventKind.Failed && events[0].Reason == AgentReason.NavmeshRemoved &&
                               world.GetAgentInfo(agent).State == AgentState.Failed,
                               "its navmesh removed, the agent fails: " + string.Join(", ", events.Select(e => e.Kind + "/" + e.Reason)));

                    // A removed agent's id is stale everywhere.
                    world.RemoveAgent(agent);
                    check.That(!world.IsValid(agent) && world.GetAgents().Length == 0, "removed");
                    check.Throws(StatusCode.InvalidHandle, "nl_agent_set_destination", () => world.SetAgentDestination(agent, new Vec3(3, 0, 5)),
                                 "a stale agent's destination");
                    check.Throws(StatusCode.InvalidHandle, "nl_agent_get_info", () => world.GetAgentInfo(agent), "a stale agent's info");
                    AgentTrajectory trajectory;
                    check.Throws(StatusCode.InvalidHandle, "nl_agent_get_trajectory", () => world.TryGetAgentTrajectory(agent, out trajectory),
                                 "a stale agent's trajectory (an error, not false)");
                    check.Throws(StatusCode.InvalidHandle, "nl_agent_remove", () => world.RemoveAgent(agent), "removing twice");
                }
            });
        }

        private static AgentId AddAgent(World world, NavmeshId navmesh, float x, float z, float jump, ulong userData)
        {
            AgentDef def = World.DefaultAgentDef();
            def.Navmesh = navmesh;
            def.Position = new Vec3(x, 0, z);
            def.Capabilities.Radius = 0.3f;
            def.Capabilities.MaxJumpDistance = jump;
            def.Capabilities.MaxJumpHeight = jump > 0 ? 1 : 0;
            def.UserData = userData;
            return world.AddAgent(def);
        }

        /// <summary>True if every item of expected occurs in actual, in that order (others may come between).</summary>
        private static bool IsSubsequence<T>(IEnumerable<T> expected, IEnumerable<T> actual)
        {
            using (IEnumerator<T> want = expected.GetEnumerator())
            {
                bool more = want.MoveNext();
                foreach (T item in actual)
                    if (more && EqualityComparer<T>.Default.Equals(item, want.Current)) more = want.MoveNext();
                return !more;
            }
        }
    }
}
