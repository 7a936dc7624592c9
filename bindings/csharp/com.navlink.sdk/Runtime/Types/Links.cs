using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_link_requirements: what taking a link asks of an agent.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct LinkRequirements
    {
        public float Gap;
        public float Rise;
        public float Drop;
        public float ClearanceWidth;
        public ulong Abilities;
        public float Length;
        public uint Reserved;
    }

    /// <summary>nl_link: a link as the world holds it. An array element that may grow: Size is the
    /// element size the library lays an output array out with (Native.nl_link_init(); World sets it).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct Link
    {
        public uint Size;
        public LinkKind Kind;
        public LinkId Id;
        public NavmeshId Navmesh;
        public Vec3 Start;
        public Vec3 End;
        public Vec3 Apex;
        public byte Bidirectional;
        public byte Generated;
        public byte Enabled;
        public byte Reserved;
        public float CostModifier;
        public uint StartPolygon;
        public uint EndPolygon;
        public uint Reserved2;
        public ulong UserData;
        public LinkRequirements Requirements;
        /// <summary>For a link to another navmesh (a cross link), the navmesh its End is on (EndPolygon is one
        /// of its polygons); the null id for a link within Navmesh. Added in 0.3.</summary>
        public NavmeshId LandingNavmesh;
        /// <summary>A cross link's: how far its end may move, seen from its start, before it stops holding;
        /// 0 for other links.</summary>
        public float Tolerance;
        /// <summary>1 if the link can be taken as the navmeshes stand now: always for a link within one
        /// navmesh; for a cross link, while its end is within Tolerance of where it was, seen from its start.</summary>
        public byte Holds;
        public fixed byte Reserved3[3];
    }

    /// <summary>nl_link_def: a link to add or the new state of one. Get one from World.DefaultLinkDef().</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct LinkDef
    {
        public uint Size;
        public LinkKind Kind;
        public Vec3 Start;
        public Vec3 End;
        public byte Bidirectional;
        public byte Enabled;
        /// <summary>0 (default): Requirements.Gap, Length, Rise and Drop are measured from the ends and the
        /// values given are ignored; 1: Requirements are taken as given (a link that asks only for an
        /// ability; a Length of 0 is measured). ClearanceWidth and Abilities are always taken as given.</summary>
        public byte RequirementsAsGiven;
        public byte Reserved;
        public float CostModifier;
        public ulong UserData;
        public LinkRequirements Requirements;
        /// <summary>The null id (default): both ends on the link's navmesh. Another navmesh: a cross link from
        /// the link's navmesh to that one, End on it (within 1 m). Both ends are given in the world as the
        /// navmeshes stand now; the link holds (Link.Holds) while the end, seen from the start, stays within
        /// Tolerance of where it is now. One-way only (Bidirectional refused), and not saved by
        /// World.SaveLinksJson (which refuses a navmesh with cross links). Added in 0.3.</summary>
        public NavmeshId LandingNavmesh;
        /// <summary>Of a cross link, metres; 0.25 by default; >= 0.</summary>
        public float Tolerance;
        public uint Reserved2;
    }

    /// <summary>nl_link_settings. PluginSettingsJson is a UTF-8 pointer borrowed for the call.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct LinkSettings
    {
        public uint Size;
        public float MinEdgeLength;
        public uint MinGroupSize;
        public uint MaxGroupSize;
        public float SampleSpacing;
        public float FalloffDistance;
        public float MaxJumpGap;
        public float MinLinkDistance;
        public float ShortLinkDistance;
        public float MaxJumpUp;
        public float JumpArcHeight;
        public float StrictForwardAngle;
        public float PermissiveForwardAngle;
        public float StrictInclineAngle;
        public float PermissiveInclineAngle;
        public float MaxDropDistance;
        public fixed float DropAngles[16];
        public uint DropAngleCount;
        public float DropSteepness;
        public float MergeDistance;
        public float ClearanceMargin;
        public uint ArcSegments;
        public IntPtr PluginSettingsJson;
        public UIntPtr PluginSettingsJsonLength;
        public float WalkFactor;
        public float WalkDistance;
    }

    /// <summary>nl_link_generation_report. Get one from Native.nl_link_generation_report_init() (Size set) before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct LinkGenerationReport
    {
        public uint Size;
        public uint Edges;
        public uint Groups;
        public uint Samples;
        public uint TakeoffPoints;
        public uint JumpCandidates;
        public uint DropCandidates;
        public uint JumpLinks;
        public uint DropLinks;
        public uint PluginLinks;
        public uint RejectedWall;
        public uint RejectedNotLedge;
        public uint RejectedDistance;
        public uint RejectedRise;
        public uint RejectedAngle;
        public uint RejectedNoLanding;
        public uint RejectedClearance;
        public uint RejectedDuplicate;
        public ulong RaysCast;
        public double MillisecondsEdges;
        public double MillisecondsTakeoff;
        public double MillisecondsJumps;
        public double MillisecondsDrops;
        public double MillisecondsMerge;
        public double MillisecondsTotal;
        public ulong BoxQueries;
        public ulong BodyTests;
        public uint RejectedWalkable;
        public uint RejectedTooShallow;
        public uint RejectedTooDeep;
        public uint Reserved;
    }
}
