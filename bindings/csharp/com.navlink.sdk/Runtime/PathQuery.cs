namespace NavLink
{
    /// <summary>One path request (nl_path_request_def) with the header's defaults: set Navmesh, Start,
    /// Goal and Agent.</summary>
    public sealed class PathQuery
    {
        public NavmeshId Navmesh;
        public Vec3 Start;
        public Vec3 Goal;
        public Vec3 SearchHalfExtents;
        public AgentCapabilities Agent;
        /// <summary>Cost per metre in area i; null: every area costs 1. Limits.AreaExcluded keeps the agent out.</summary>
        public float[] AreaCosts;
        public float LinkCost;
        public uint MaxNodes;
        public bool AcceptPartial;

        public PathQuery()
        {
            LibraryCheck.EnsureLoaded();
            PathRequestDef d = Native.nl_default_path_request_def();
            SearchHalfExtents = d.SearchHalfExtents;
            Agent = d.Agent;
            LinkCost = d.LinkCost;
            MaxNodes = d.MaxNodes;
            AcceptPartial = d.AcceptPartial != 0;
        }

        public PathQuery(NavmeshId navmesh, Vec3 start, Vec3 goal, AgentCapabilities agent) : this()
        {
            Navmesh = navmesh;
            Start = start;
            Goal = goal;
            Agent = agent;
        }
    }

    /// <summary>What a finished request found: nl_path_result and its points.</summary>
    public sealed class PathResult
    {
        public PathResult(PathResultInfo info, PathPoint[] points)
        {
            Info = info;
            Points = points;
        }

        public PathResultInfo Info { get; private set; }
        public PathPoint[] Points { get; private set; }
        public PathOutcome Outcome { get { return Info.Outcome; } }
        /// <summary>For PathOutcome.Failed: why.</summary>
        public StatusCode Status { get { return Info.Status; } }
        public float Length { get { return Info.Length; } }
        public float Cost { get { return Info.Cost; } }
        public uint LinksUsed { get { return Info.LinksUsed; } }
    }
}
