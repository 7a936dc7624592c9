using System;

namespace NavLink
{
    // What some of the header's structs have in C# besides their fields (Generated/*.g.cs declares the fields,
    // from the headers): constructors and helpers. No field may be added here: the layout test holds every
    // struct to its C twin.

    public partial struct NavLinkVersion
    {
        public override string ToString() { return Major + "." + Minor + "." + Patch; }
    }

    public partial struct Ray
    {
        public Ray(Vec3 origin, Vec3 direction, float maxDistance)
        {
            Origin = origin;
            Direction = direction;
            MaxDistance = maxDistance;
        }
    }

    public partial struct Segment
    {
        public Segment(Vec3 from, Vec3 to)
        {
            From = from;
            To = to;
        }
    }

    public partial struct NavmeshRay
    {
        public NavmeshRay(Vec3 start, uint startPolygon, Vec3 end)
        {
            Start = start;
            StartPolygon = startPolygon;
            End = end;
        }
    }

    public partial struct TileCoord : IEquatable<TileCoord>
    {
        public TileCoord(int x, int z)
        {
            X = x;
            Z = z;
        }

        public bool Equals(TileCoord o) { return X == o.X && Z == o.Z; }
        public override bool Equals(object o) { return o is TileCoord && Equals((TileCoord)o); }
        public override int GetHashCode() { return X * 31 + Z; }
        public static bool operator ==(TileCoord a, TileCoord b) { return a.Equals(b); }
        public static bool operator !=(TileCoord a, TileCoord b) { return !a.Equals(b); }
        public override string ToString() { return "(" + X + ", " + Z + ")"; }
    }

    public unsafe partial struct AgentTrajectory
    {
        /// <summary>Points[k], k in 0..3 (C's float[4][3], x y z of each point in turn). For TrajectoryKind.Fall;
        /// otherwise From, From, To, To.</summary>
        public Vec3 Point(int k)
        {
            if (k < 0 || k > 3) throw new ArgumentOutOfRangeException("k");
            fixed (float* p = Points) return new Vec3(p[3 * k], p[3 * k + 1], p[3 * k + 2]);
        }
    }

    /// <summary>A request that finished since the last World.TakeFinishedPaths: its ticket and outcome.</summary>
    public struct FinishedPath : IEquatable<FinishedPath>
    {
        public readonly PathTicket Ticket;
        public readonly PathOutcome Outcome;

        public FinishedPath(PathTicket ticket, PathOutcome outcome)
        {
            Ticket = ticket;
            Outcome = outcome;
        }

        public bool Equals(FinishedPath o) { return Ticket.Equals(o.Ticket) && Outcome == o.Outcome; }
        public override bool Equals(object o) { return o is FinishedPath && Equals((FinishedPath)o); }
        public override int GetHashCode() { return Ticket.GetHashCode() * 31 + (int)Outcome; }
        public override string ToString() { return Ticket + ": " + Outcome; }
    }
}
