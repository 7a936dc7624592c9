using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;
using NavLink;

namespace NavLink.Tests
{
    // Agents on the bridge level (tests/abi/agents_test.c's): a jumper takes a generated jump across the gap
    // while a walker goes round by the bridge, as the states read in bulk and the step's events say; the
    // trajectory of the jump mid-flight; bad input refused.
    internal static class AgentTests
    {
        private const float Dt = 1.0f / 30.0f;
        private const int MaxSteps = 30 * 20;

        public static void Run(Checks check)
        {
            check.Run("agents: a walker goes round, a jumper jumps", () =>
            {
                AgentDef defaults = World.DefaultAgentDef();
                check.That(defaults.Size == (uint)Marshal.SizeOf(typeof(AgentDef)) && defaults.Height == 2 && defaults.MaxSpeed == 3.5f &&
                           defaults.MaxAcceleration == 8 && Math.Abs(defaults.Gravity - 9.81f) < 1e-6f && defaults.Avoidance == 1 &&
                           defaults.Capabilities.Radius == 0.6f && defaults.Navmesh.IsNull,
                           "the default agent def");
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

            check.Run("agents: bad input", () =>
            {
                check.Throws(StatusBits.InvalidArgument, "agent_paths_per_step", () => new World(new WorldOptions { AgentPathsPerStep = 0 }),
                             "a world that plans no agent paths");
                using (var world = new World(new WorldOptions { WorkerCount = 1, AgentPathsPerStep = 1 }))
                {
                    NavmeshId navmesh = TestLevels.AddBridgeLevel(world);
                    AgentId agent = AddAgent(world, navmesh, 1, 2, 0, 0);
                    AgentDef off = World.DefaultAgentDef();
                    off.Navmesh = navmesh;
                    off.Position = new Vec3(5, 0, 2);  // over the gap
                    check.Throws(StatusBits.NotFound, "def->position is not on the navmesh", () => world.AddAgent(off), "an agent off the navmesh");
                    check.Throws(StatusBits.NotFound, "nearest navmesh point", () => world.SetAgentDestination(agent, new Vec3(5, 0, 2)),
                                 "a destination off the navmesh");
                    check.That(world.GetAgentInfo(agent).HasDestination == 0, "a refused destination is not kept");
                    check.Throws(StatusBits.InvalidArgument, "point", () => world.SetAgentDestination(agent, new Vec3(float.NaN, 0, 0)),
                                 "a NaN destination");
                    check.Throws(StatusBits.InvalidArgument, "dt", () => world.Step(float.NaN), "a NaN step");
                    check.Throws(StatusBits.InvalidArgument, "max_speed", () => world.SetAgentSpeed(agent, -1, 1), "a negative speed");
                    AgentCapabilities nanRadius = TestLevels.Walker();
                    nanRadius.Radius = float.NaN;
                    check.Throws(StatusBits.InvalidArgument, "radius", () => world.SetAgentCapabilities(agent, nanRadius), "a NaN radius");

                    // A raw call must set the element size of its output array, as in C.
                    var infos = new AgentInfo[1];
                    uint count;
                    unsafe
                    {
                        fixed (AgentInfo* p = infos)
                            check.Status(Native.nl_world_get_agents(world.DangerousGetPointer(), p, 1, &count),
                                         StatusBits.InvalidArgument, "size", "a raw list with an unset element size");
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
                    check.Throws(StatusBits.InvalidHandle, "nl_agent_set_destination", () => world.SetAgentDestination(agent, new Vec3(3, 0, 5)),
                                 "a stale agent's destination");
                    check.Throws(StatusBits.InvalidHandle, "nl_agent_get_info", () => world.GetAgentInfo(agent), "a stale agent's info");
                    AgentTrajectory trajectory;
                    check.Throws(StatusBits.InvalidHandle, "nl_agent_get_trajectory", () => world.TryGetAgentTrajectory(agent, out trajectory),
                                 "a stale agent's trajectory (an error, not false)");
                    check.Throws(StatusBits.InvalidHandle, "nl_agent_remove", () => world.RemoveAgent(agent), "removing twice");
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
