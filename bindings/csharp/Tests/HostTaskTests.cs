using System;
using System.Linq;
using System.Runtime.InteropServices;
using System.Threading;
using AOT;
using NavLink;

namespace NavLink.Tests
{
    // A world whose batch work runs on the host's task system (WorldOptions.TaskEnqueueFn/TaskFinishFn):
    // an inline host written in C# (each task run at once, in pieces of minRange; no handle to finish)
    // gives the same rays and links as NavLink's own threads, and is really called.
    internal static class HostTaskTests
    {
        private static int enqueues, finishes;
        // Kept alive for as long as native code may call them (static fields, as IL2CPP wants).
        private static readonly NativeCallbacks.TaskEnqueueFn Enqueue = EnqueueInline;
        private static readonly NativeCallbacks.TaskFinishFn Finish = FinishCounted;

        [MonoPInvokeCallback(typeof(NativeCallbacks.TaskEnqueueFn))]
        private static IntPtr EnqueueInline(IntPtr user, IntPtr task, IntPtr taskContext, uint itemCount, uint minRange)
        {
            Interlocked.Increment(ref enqueues);
            var run = (NativeCallbacks.TaskFn)Marshal.GetDelegateForFunctionPointer(task, typeof(NativeCallbacks.TaskFn));
            uint step = Math.Max(1u, minRange);
            for (uint begin = 0; begin < itemCount; begin += step)
                run(taskContext, begin, Math.Min(itemCount, begin + step), 0);
            return IntPtr.Zero;
        }

        [MonoPInvokeCallback(typeof(NativeCallbacks.TaskFinishFn))]
        private static void FinishCounted(IntPtr user, IntPtr hostTask) { Interlocked.Increment(ref finishes); }

        private static string Run(World world)
        {
            TestLevels.AddGapLevel(world);
            var rays = new Ray[2400];
            for (int x = 0; x < 60; ++x)
                for (int z = 0; z < 40; ++z)
                    rays[x * 40 + z] = new Ray(new Vec3(-13 + 0.45f * x, 5, -6 + 0.3f * z), new Vec3(0, -1, 0), 100);
            RayHit[] hits = world.CastRays(rays);
            NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
            world.GenerateLinks(navmesh);
            Link[] links = world.GetLinks(navmesh);
            // Everything but the ids (they carry the world's tag), as text with the floats' bits.
            Func<float, string> bits = f => BitConverter.ToInt32(BitConverter.GetBytes(f), 0).ToString("x8");
            Func<Vec3, string> v = p => bits(p.X) + bits(p.Y) + bits(p.Z);
            return string.Join(",", hits.Select(h => h.Hit + bits(h.Distance))) + "|" +
                   string.Join(",", links.Select(l => l.Kind + v(l.Start) + v(l.End) + v(l.Apex) + bits(l.Requirements.Gap))) +
                   "|" + links.Length;
        }

        public static void Run(Checks check)
        {
            check.Run("host task system: same results as NavLink's threads, callbacks called", () =>
            {
                string reference;
                using (var world = new World(new WorldOptions { WorkerCount = 2, PathWorkerCount = 0 }))
                    reference = Run(world);
                check.That(!reference.EndsWith("|0"), "the gap level has links");
                var options = new WorldOptions
                {
                    WorkerCount = 1,
                    PathWorkerCount = 0,
                    TaskEnqueueFn = Marshal.GetFunctionPointerForDelegate(Enqueue),
                    TaskFinishFn = Marshal.GetFunctionPointerForDelegate(Finish),
                };
                using (var world = new World(options))
                {
                    check.That(world.WorkerCount == 1, "worker count " + world.WorkerCount);
                    check.That(Run(world) == reference, "rays and links equal the TBB world's");
                }
                check.That(enqueues > 0 && finishes == 0, enqueues + " enqueues, " + finishes + " finishes");
                options.TaskFinishFn = IntPtr.Zero;
                check.Throws(StatusCode.InvalidArgument, "task_finish_fn", () => new World(options), "enqueue without finish");
            });
        }
    }
}
