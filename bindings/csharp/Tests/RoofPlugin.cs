using System;
using System.Runtime.InteropServices;
using AOT;
using NavLink;

namespace NavLink.Tests
{
    // A navmesh-builder plugin written in C# and registered with nl_plugin_register: it covers the level's
    // bounds with one square at the level's highest vertex (the C API guide's "roof" example). It drives the
    // plugin side of the ABI from managed code: the entry function, nl_plugin_info, the host table
    // (get_level_triangles, set_error) and the navmesh sink.
    internal static class RoofPlugin
    {
        public const string Name = "csharp-roof";
        public const string NoTrianglesMessage = "csharp-roof: the level has no triangles";

        private static readonly NativeCallbacks.PluginEntryFn EntryDelegate = Entry;
        private static readonly NativeCallbacks.NavmeshBuildFn BuildDelegate = Build;
        // Strings a plugin hands over must outlive it: allocated once, never freed.
        private static readonly IntPtr NameUtf8 = Utf8.AllocZ(Name);
        private static readonly IntPtr VersionUtf8 = Utf8.AllocZ("1.0");
        private static readonly IntPtr DescriptionUtf8 = Utf8.AllocZ("one square over the whole level");
        private static readonly IntPtr NoTrianglesUtf8 = Utf8.AllocZ(NoTrianglesMessage);
        public const string Used = "{\"at\":\"the highest vertex\"}";
        private static readonly IntPtr UsedUtf8 = Utf8.AllocZ(Used);
        private static readonly int UsedLength = System.Text.Encoding.UTF8.GetByteCount(Used);

        public static NativeCallbacks.PluginEntryFn EntryFunction { get { return EntryDelegate; } }

        [MonoPInvokeCallback(typeof(NativeCallbacks.PluginEntryFn))]
        private static unsafe StatusCode Entry(uint hostAbiVersion, IntPtr host, IntPtr outInfo)
        {
            if (hostAbiVersion < 1) return StatusCode.Failure | StatusCode.VersionMismatch;
            var info = (PluginInfo*)outInfo;
            info->AbiVersion = PluginAbi.Version;
            info->Name = NameUtf8;
            info->Version = VersionUtf8;
            info->Description = DescriptionUtf8;
            info->Kinds = PluginKinds.NavmeshBuilder;
            info->NavmeshBuilder.Build = Marshal.GetFunctionPointerForDelegate(BuildDelegate);
            return StatusCode.Success;
        }

        [MonoPInvokeCallback(typeof(NativeCallbacks.NavmeshBuildFn))]
        private static unsafe StatusCode Build(IntPtr state, IntPtr hostPointer, IntPtr defPointer, IntPtr sink, IntPtr sinkContext)
        {
            try
            {
                var host = (PluginHost*)hostPointer;
                var def = (NavmeshBuildDef*)defPointer;
                var getTriangles = (NativeCallbacks.HostGetLevelTrianglesFn)Marshal.GetDelegateForFunctionPointer(
                    host->GetLevelTriangles, typeof(NativeCallbacks.HostGetLevelTrianglesFn));
                uint vertexCount, triangleCount;
                StatusCode status = getTriangles(host->Context, null, 0, &vertexCount, null, 0, &triangleCount);
                if (Status.Failed(status)) return status;
                if (triangleCount == 0)
                {
                    var setError = (NativeCallbacks.HostSetErrorFn)Marshal.GetDelegateForFunctionPointer(
                        host->SetError, typeof(NativeCallbacks.HostSetErrorFn));
                    setError(host->Context, NoTrianglesUtf8);
                    return StatusCode.Failure | StatusCode.NotFound;
                }
                var vertices = new float[3 * vertexCount];
                var indices = new uint[3 * triangleCount];
                fixed (float* v = vertices)
                fixed (uint* t = indices)
                    status = getTriangles(host->Context, v, vertexCount, &vertexCount, t, triangleCount, &triangleCount);
                if (Status.Failed(status)) return status;

                float minX = float.MaxValue, minZ = float.MaxValue, maxX = float.MinValue, maxY = float.MinValue, maxZ = float.MinValue;
                for (int i = 0; i < vertexCount; ++i)
                {
                    minX = Math.Min(minX, vertices[3 * i]);
                    maxX = Math.Max(maxX, vertices[3 * i]);
                    maxY = Math.Max(maxY, vertices[3 * i + 1]);
                    minZ = Math.Min(minZ, vertices[3 * i + 2]);
                    maxZ = Math.Max(maxZ, vertices[3 * i + 2]);
                }
                // Counter-clockwise seen from above: (min, min) (min, max) (max, max) (max, min) in x-z.
                float* quad = stackalloc float[12];
                quad[0] = minX; quad[1] = maxY; quad[2] = minZ;
                quad[3] = minX; quad[4] = maxY; quad[5] = maxZ;
                quad[6] = maxX; quad[7] = maxY; quad[8] = maxZ;
                quad[9] = maxX; quad[10] = maxY; quad[11] = minZ;
                uint* square = stackalloc uint[4];
                for (uint k = 0; k < 4; ++k) square[k] = k;
                byte corners = 4;

                NavmeshDef navmesh = default(NavmeshDef);
                navmesh.Size = (uint)sizeof(NavmeshDef);
                navmesh.Vertices = (IntPtr)quad;
                navmesh.VertexCount = 4;
                navmesh.Indices = (IntPtr)square;
                navmesh.PolygonVertexCounts = (IntPtr)(&corners);
                navmesh.PolygonCount = 1;
                navmesh.AgentType = def->AgentType;
                if (host->Size >= (uint)sizeof(PluginHost))
                {
                    // A host that keeps what a build used.
                    var record = (NativeCallbacks.HostRecordBuildSettingsFn)Marshal.GetDelegateForFunctionPointer(
                        host->RecordBuildSettings, typeof(NativeCallbacks.HostRecordBuildSettingsFn));
                    status = record(host->Context, UsedUtf8, (UIntPtr)UsedLength);
                    if (Status.Failed(status)) return status;
                }
                var send = (NativeCallbacks.NavmeshSinkFn)Marshal.GetDelegateForFunctionPointer(sink, typeof(NativeCallbacks.NavmeshSinkFn));
                return send(sinkContext, (IntPtr)(&navmesh));
            }
            catch (Exception e)
            {
                // Never let an exception unwind into the library.
                Console.Error.WriteLine("csharp-roof: " + e);
                return StatusCode.Failure | StatusCode.InternalError;
            }
        }
    }
}
