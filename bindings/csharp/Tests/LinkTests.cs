using System;
using System.Collections.Generic;
using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // Link generation on the gap level, manual links, JSON, progress callbacks.
    internal static class LinkTests
    {
        public static void Run(Checks check)
        {
            check.Run("generated jump links", () =>
            {
                using (var world = new World())
                {
                    TestLevels.AddGapLevel(world);
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
                    var fractions = new List<float>();
                    int caller = System.Threading.Thread.CurrentThread.ManagedThreadId, otherThread = 0;
                    LinkGenerationReport report = world.GenerateLinks(navmesh, null, (fraction, stage) =>
                    {
                        fractions.Add(fraction);
                        if (System.Threading.Thread.CurrentThread.ManagedThreadId != caller) ++otherThread;
                        return true;
                    });
                    Link[] links = world.GetLinks(navmesh);
                    check.That(report.JumpLinks >= 5 && report.DropLinks == 0 && links.Length == report.JumpLinks,
                               report.JumpLinks + " jumps, " + report.DropLinks + " drops, " + links.Length + " links listed");
                    check.That(links.All(l => l.Kind == LinkKind.Jump && l.Generated == 1 && l.Bidirectional == 1 &&
                                             l.Navmesh.Equals(navmesh)), "all generated bidirectional jumps");
                    check.That(links.All(l => Math.Abs(l.Requirements.Gap - 2.0f) <= 0.05f &&
                                             l.Requirements.Length >= 3.1f && l.Requirements.Length <= 3.9f &&
                                             Math.Abs(l.Requirements.Length - l.Start.HorizontalDistance(l.End)) < 1e-3f),
                               "gaps of 2 m rim to rim, lengths 3.1-3.9 m (the ends' horizontal distance)");
                    check.That(links.All(l => Math.Min(l.Start.X, l.End.X) < -1 && Math.Max(l.Start.X, l.End.X) > 1),
                               "one end on each platform");
                    check.That(links.All(l => l.Apex.Y > Math.Max(l.Start.Y, l.End.Y)), "a jump's apex is above its ends");
                    check.That(fractions.Count >= 2 && fractions.Last() == 1.0f && otherThread == 0,
                               "progress: " + fractions.Count + " calls on the caller's thread, ending at 1");

                    // Settings from JSON: a max_jump_gap below the gap leaves nothing to jump.
                    LinkSettings shortJumps = World.LinkSettingsFromJson("{\"max_jump_gap\": 1.8}");
                    check.Near(shortJumps.MaxJumpGap, 1.8f, 1e-6f, "max_jump_gap from JSON");
                    LinkGenerationReport none = world.GenerateLinks(navmesh, shortJumps);
                    check.That(none.JumpLinks == 0 && none.RejectedDistance > 0 && world.GetLinks(navmesh).Length == 0,
                               "max_jump_gap 1.8: no jumps, " + none.RejectedDistance + " rejected for distance");
                    check.Throws(StatusCode.InvalidArgument, "max_link_dist", () => World.LinkSettingsFromJson("{\"max_link_dist\": 3}"),
                                 "an unknown settings key");

                    // Cancelling from progress leaves the links as they were; an exception cancels and comes back.
                    world.GenerateLinks(navmesh);
                    int before = world.GetLinks(navmesh).Length;
                    check.Throws(StatusCode.Cancelled, "", () => world.GenerateLinks(navmesh, null, (f, s) => false), "a cancelled generation");
                    check.That(world.GetLinks(navmesh).Length == before, "a cancelled generation changes nothing");
                    try
                    {
                        world.GenerateLinks(navmesh, null, (f, s) => { throw new InvalidOperationException("boom"); });
                        check.That(false, "a throwing progress callback fails the generation");
                    }
                    catch (NavLinkException e)
                    {
                        check.That(e.Has(StatusCode.Cancelled) && e.InnerException is InvalidOperationException,
                                   "the callback's exception comes back as the inner exception");
                    }

                    // A wall in the gap: the update in its box removes every jump, as a full generation would.
                    TestLevels.AddBox(world, -0.1f, -20, -6, 0.1f, 6, 6);
                    LinkGenerationReport walled = world.UpdateLinksInBox(navmesh, new Vec3(-0.2f, -21, -7), new Vec3(0.2f, 7, 7));
                    check.That(walled.JumpLinks == 0 && world.GetLinks(navmesh).Length == 0,
                               "after the wall: " + walled.JumpLinks + " jumps (" + walled.RejectedClearance + " refused for clearance)");
                    check.That(world.RemoveGeneratedLinks(navmesh) == 0, "nothing generated is left to remove");
                }
            });

            check.Run("manual links and JSON", () =>
            {
                using (var world = new World())
                {
                    TestLevels.AddGapLevel(world);
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
                    world.GenerateLinks(navmesh);
                    int generated = world.GetLinks(navmesh).Length;

                    LinkDef def = World.DefaultLinkDef();
                    check.That(def.Kind == LinkKind.Manual && def.Enabled == 1 && def.CostModifier == 1 && def.RequirementsAsGiven == 0,
                               "default link def");
                    def.Start = new Vec3(-5, 0, 4);
                    def.End = new Vec3(5, 0, 4);
                    def.UserData = 7;
                    def.Requirements.Gap = 99;  // measured from the ends instead
                    LinkId manual = world.AddLink(navmesh, def);
                    Link got = world.GetLink(manual);
                    check.That(got.Kind == LinkKind.Manual && got.Generated == 0 && got.UserData == 7 && got.Id.Equals(manual) &&
                               got.Navmesh.Equals(navmesh) && Math.Abs(got.Requirements.Gap - 10) < 1e-4f,
                               "the manual link, its gap measured from the ends: " + got.Requirements.Gap);

                    // Requirements taken as given: a link across the gap that asks only for an ability.
                    LinkDef ability = World.DefaultLinkDef();
                    ability.Start = new Vec3(-5, 0, -4);
                    ability.End = new Vec3(5, 0, -4);
                    ability.RequirementsAsGiven = 1;
                    ability.Requirements.Abilities = 4;
                    LinkId abilityLink = world.AddLink(navmesh, ability);
                    Link asGiven = world.GetLink(abilityLink);
                    check.That(asGiven.Requirements.Gap == 0 && asGiven.Requirements.Rise == 0 && asGiven.Requirements.Abilities == 4 &&
                               Math.Abs(asGiven.Requirements.Length - 10) < 1e-4f,
                               "requirements as given (gap " + asGiven.Requirements.Gap + "), the length of 0 measured: " +
                               asGiven.Requirements.Length);
                    AgentCapabilities able = World.DefaultAgentCapabilities();
                    able.Abilities = 4;
                    PathResult across = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, able));
                    check.That(across.Outcome == PathOutcome.Complete && across.Points.Any(q => q.Link.Equals(abilityLink)),
                               "a walker with the ability crosses on that link: " + across.Outcome);
                    PathResult stuck = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint,
                                                                    World.DefaultAgentCapabilities()));
                    check.That(stuck.Outcome == PathOutcome.Partial, "a walker without it does not: " + stuck.Outcome);
                    world.RemoveLink(abilityLink);
                    def.Enabled = 0;
                    world.UpdateLink(manual, def);
                    check.That(world.GetLink(manual).Enabled == 0, "updated: disabled");

                    check.That(world.RemoveGeneratedLinks(navmesh) == generated && world.GetLinks(navmesh).Length == 1,
                               "removing the generated links keeps the manual one");
                    world.GenerateLinks(navmesh);
                    string json = world.SaveLinksJson(navmesh);
                    check.That(json.Contains("navlink-links"), "the JSON names its schema");
                    check.That(world.LoadLinksJson(navmesh, json) == generated + 1, "loading the JSON back gives every link");
                    check.That(!world.IsValid(manual), "loaded links get new ids: the old one is stale");
                    Link stale;
                    check.That(!world.TryGetLink(manual, out stale), "TryGetLink of a stale link is false");
                    check.Throws(StatusCode.InvalidHandle, "nl_link_remove", () => world.RemoveLink(manual), "removing a stale link");
                    check.Throws(StatusCode.ParseError, "nl_navmesh_load_links_json", () => world.LoadLinksJson(navmesh, "[1,"),
                                 "malformed links JSON");
                    def.End = new Vec3(0, 0, 0);  // over the gap: off the navmesh
                    check.Throws(StatusCode.InvalidArgument, "def->end", () => world.AddLink(navmesh, def), "a link ending off the navmesh");
                }
            });

            check.Run("links JSON for another body", () =>
            {
                var logged = new List<string>();
                using (var world = new World(new WorldOptions { Log = (level, status, message) => { lock (logged) logged.Add(message); } }))
                {
                    NavmeshId wide = TestLevels.AddGapNavmeshWithLinks(world);  // radius 0.6
                    int count = world.GetLinks(wide).Length;
                    string json = world.SaveLinksJson(wide);
                    check.That(json.Contains("\"made_for\""), "the saved JSON records what its links were made for");

                    AgentType slim = World.DefaultAgentType();
                    slim.Radius = 0.3f;
                    NavmeshId narrow = world.BuildNavmesh(slim);
                    check.Throws(StatusCode.InvalidArgument, "radius 0.6", () => world.LoadLinksJson(narrow, json),
                                 "links for radius 0.6 into a navmesh for radius 0.3 (names theirs)");
                    check.Throws(StatusCode.InvalidArgument, "radius 0.3", () => world.LoadLinksJson(narrow, json, false),
                                 "links for radius 0.6 into a navmesh for radius 0.3 (names ours)");
                    check.That(world.GetLinks(narrow).Length == 0, "a refused load changes nothing");
                    lock (logged) logged.Clear();
                    check.That(world.LoadLinksJson(narrow, json, anyBody: true) == count, "anyBody loads them all");
                    check.That(world.GetLinks(narrow).Length == count, "the narrow navmesh has them");
                    lock (logged)
                        check.That(logged.Any(m => m.Contains("radius 0.6") && m.Contains("radius 0.3")),
                                   "anyBody warns to the log, naming both bodies: " + string.Join(" | ", logged));

                    NavmeshId same = world.BuildNavmesh(World.DefaultAgentType());
                    check.That(world.LoadLinksJson(same, json) == count, "a navmesh for the same body loads them");
                    check.That(world.LoadLinksJson(wide, json) == count, "and so does the one they were saved from");
                }
            });
        }
    }
}
