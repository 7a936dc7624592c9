using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // Ids are passed by value: {index1, generation}, all zero is null (navlink.h). Each kind is its own
    // type so a mesh id cannot be passed where a link id is expected.

    [StructLayout(LayoutKind.Sequential)]
    public struct MeshId : IEquatable<MeshId>
    {
        public uint Index1, Generation;
        public bool IsNull { get { return Index1 == 0u; } }
        public bool Equals(MeshId o) { return Index1 == o.Index1 && Generation == o.Generation; }
        public override bool Equals(object o) { return o is MeshId && Equals((MeshId)o); }
        public override int GetHashCode() { return (int)(Index1 * 31u + Generation); }
        public override string ToString() { return "mesh{" + Index1 + "," + Generation + "}"; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshId : IEquatable<NavmeshId>
    {
        public uint Index1, Generation;
        public bool IsNull { get { return Index1 == 0u; } }
        public bool Equals(NavmeshId o) { return Index1 == o.Index1 && Generation == o.Generation; }
        public override bool Equals(object o) { return o is NavmeshId && Equals((NavmeshId)o); }
        public override int GetHashCode() { return (int)(Index1 * 31u + Generation); }
        public override string ToString() { return "navmesh{" + Index1 + "," + Generation + "}"; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct LinkId : IEquatable<LinkId>
    {
        public uint Index1, Generation;
        public bool IsNull { get { return Index1 == 0u; } }
        public bool Equals(LinkId o) { return Index1 == o.Index1 && Generation == o.Generation; }
        public override bool Equals(object o) { return o is LinkId && Equals((LinkId)o); }
        public override int GetHashCode() { return (int)(Index1 * 31u + Generation); }
        public override string ToString() { return "link{" + Index1 + "," + Generation + "}"; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct PathTicket : IEquatable<PathTicket>
    {
        public uint Index1, Generation;
        public bool IsNull { get { return Index1 == 0u; } }
        public bool Equals(PathTicket o) { return Index1 == o.Index1 && Generation == o.Generation; }
        public override bool Equals(object o) { return o is PathTicket && Equals((PathTicket)o); }
        public override int GetHashCode() { return (int)(Index1 * 31u + Generation); }
        public override string ToString() { return "ticket{" + Index1 + "," + Generation + "}"; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct AgentId : IEquatable<AgentId>
    {
        public uint Index1, Generation;
        public bool IsNull { get { return Index1 == 0u; } }
        public bool Equals(AgentId o) { return Index1 == o.Index1 && Generation == o.Generation; }
        public override bool Equals(object o) { return o is AgentId && Equals((AgentId)o); }
        public override int GetHashCode() { return (int)(Index1 * 31u + Generation); }
        public override string ToString() { return "agent{" + Index1 + "," + Generation + "}"; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct PluginId : IEquatable<PluginId>
    {
        public uint Index1, Generation;
        public bool IsNull { get { return Index1 == 0u; } }
        public bool Equals(PluginId o) { return Index1 == o.Index1 && Generation == o.Generation; }
        public override bool Equals(object o) { return o is PluginId && Equals((PluginId)o); }
        public override int GetHashCode() { return (int)(Index1 * 31u + Generation); }
        public override string ToString() { return "plugin{" + Index1 + "," + Generation + "}"; }
    }
}
