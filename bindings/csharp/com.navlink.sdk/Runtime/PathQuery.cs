namespace NavLink
{
    /// <summary>One path request (nl_path_request_def) with the header's defaults: set Navmesh, Start,
    /// Goal and Capabilities.</summary>
    public sealed class PathQuery
    {
        public NavmeshId Navmesh;
        public Vec3 Start;
        public Vec3 Goal;
        public Vec3 SearchHalfExtents;
        public AgentCapabilities Capabilities;
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
            Capabilities = d.Capabilities;
            LinkCost = d.LinkCost;
            MaxNodes = d.MaxNodes;
            AcceptPartial = d.AcceptPartial != 0;
        }

        public PathQuery(NavmeshId navmesh, Vec3 start, Vec3 goal, AgentCapabilities capabilities) : this()
        {
            Navmesh = navmesh;
            Start = start;
            Goal = goal;
            Capabilities = capabilities;
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

    /// <summary>Why a request's path falls short of its goal (World.ExplainPath, nl_path_shortfall): Reason
    /// None when it reaches the goal or an end is off the navmesh; Text says the same as a sentence naming
    /// the field to change ("" for None).</summary>
    public sealed class PathShortfall
    {
        public unsafe PathShortfall(PathShortfallInfo info)
        {
            Info = info;
            Text = Utf8.Decode(info.Text, 256);
        }

        public PathShortfallInfo Info { get; private set; }
        public PathShortfallReason Reason { get { return Info.Reason; } }
        /// <summary>For PathShortfallReason.LinkBeyondBody: what the link asks that the body lacks.</summary>
        public LinkLimit Limit { get { return Info.Limit; } }
        /// <summary>LinkBeyondBody: what the link needs, metres (for LinkLimit.Width the body's diameter);
        /// BodyTooWide: the body's radius.</summary>
        public float Needed { get { return Info.Needed; } }
        /// <summary>LinkBeyondBody: what the body can, metres (for LinkLimit.Width the link's clearance);
        /// BodyTooWide: the navmesh's radius.</summary>
        public float Has { get { return Info.Has; } }
        /// <summary>The link would be taken from its end to its start.</summary>
        public bool Reversed { get { return Info.Reversed != 0; } }
        /// <summary>LinkLimit.Abilities: the bits the body lacks.</summary>
        public ulong MissingAbilities { get { return Info.MissingAbilities; } }
        /// <summary>LinkBeyondBody: the link (of the request's navmesh, or a cross link of another); the null id otherwise.</summary>
        public LinkId Link { get { return Info.Link; } }
        /// <summary>Where the body would take the link, in the world.</summary>
        public Vec3 LinkStart { get { return Info.LinkStart; } }
        /// <summary>The sentence, e.g. "a drop at (12, 4, 3) would get there: it needs a drop of 4.2 m, and the
        /// body drops 4 m (max_drop_height)"; "" for PathShortfallReason.None.</summary>
        public string Text { get; private set; }

        public override string ToString() { return Text.Length > 0 ? Text : Reason.ToString(); }
    }
}
