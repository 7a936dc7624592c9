using System;

namespace NavLink
{
    /// <summary>The body a navmesh query is for (nl_query_filter), as a PathQuery describes it: its capabilities
    /// (the links it can take, the room a wider body needs) and its area costs (an area of cost
    /// Limits.AreaExcluded is kept out of; other costs do not matter to these queries). new QueryFilter() is
    /// nl_default_query_filter(): a default walker that keeps out of no area. World's query methods take null
    /// for that too.</summary>
    public sealed class QueryFilter
    {
        public AgentCapabilities Capabilities;
        /// <summary>Cost per metre in area i (at most 256); null: no area is excluded.</summary>
        public float[] AreaCosts;

        public QueryFilter()
        {
            LibraryCheck.EnsureLoaded();
            Capabilities = Native.nl_default_query_filter().Capabilities;
        }

        public QueryFilter(AgentCapabilities capabilities, float[] areaCosts = null)
        {
            LibraryCheck.EnsureLoaded();
            Capabilities = capabilities;
            AreaCosts = areaCosts;
        }

        /// <summary>The C struct over areaCosts (this.AreaCosts, pinned by the caller for the call).</summary>
        internal unsafe QueryFilterDef ToDef(float* areaCosts)
        {
            QueryFilterDef def = Native.nl_default_query_filter();
            def.Capabilities = Capabilities;
            def.AreaCosts = (IntPtr)areaCosts;
            def.AreaCostCount = (uint)(AreaCosts == null ? 0 : AreaCosts.Length);
            return def;
        }
    }
}
