namespace NavLink
{
    // The header's inline initialisers (NL_DEFINE_OUTPUT_INIT): a zeroed output struct with Size set. They
    // are static inline in navlink.h, so the library does not export them: these are their C# twins, under
    // the same names. Use them before a raw Native call that fills such a struct; for an output array of
    // growable elements (Link, PathPoint, RayHit, PathFinished, AgentInfo, AgentEvent) the library reads
    // the element size from the FIRST element: `links[0] = Native.nl_link_init();`. World's methods do
    // this themselves.
    public static unsafe partial class Native
    {
        public static MeshInfo nl_mesh_info_init() { var v = default(MeshInfo); v.Size = (uint)sizeof(MeshInfo); return v; }

        public static RayHit nl_ray_hit_init() { var v = default(RayHit); v.Size = (uint)sizeof(RayHit); return v; }

        public static NavmeshInfo nl_navmesh_info_init() { var v = default(NavmeshInfo); v.Size = (uint)sizeof(NavmeshInfo); return v; }

        public static NavPolygon nl_nav_polygon_init() { var v = default(NavPolygon); v.Size = (uint)sizeof(NavPolygon); return v; }

        public static Link nl_link_init() { var v = default(Link); v.Size = (uint)sizeof(Link); return v; }

        public static LinkGenerationReport nl_link_generation_report_init()
        {
            var v = default(LinkGenerationReport);
            v.Size = (uint)sizeof(LinkGenerationReport);
            return v;
        }

        public static PathPoint nl_path_point_init() { var v = default(PathPoint); v.Size = (uint)sizeof(PathPoint); return v; }

        public static PathResultInfo nl_path_result_init() { var v = default(PathResultInfo); v.Size = (uint)sizeof(PathResultInfo); return v; }

        public static PathShortfallInfo nl_path_shortfall_init()
        {
            var v = default(PathShortfallInfo);
            v.Size = (uint)sizeof(PathShortfallInfo);
            return v;
        }

        public static PathFinished nl_path_finished_init() { var v = default(PathFinished); v.Size = (uint)sizeof(PathFinished); return v; }

        public static PathQueueStats nl_path_queue_stats_init() { var v = default(PathQueueStats); v.Size = (uint)sizeof(PathQueueStats); return v; }

        public static NavmeshRaycastHit nl_navmesh_raycast_hit_init()
        {
            var v = default(NavmeshRaycastHit);
            v.Size = (uint)sizeof(NavmeshRaycastHit);
            return v;
        }

        public static AgentInfo nl_agent_info_init() { var v = default(AgentInfo); v.Size = (uint)sizeof(AgentInfo); return v; }

        public static AgentTrajectory nl_agent_trajectory_init()
        {
            var v = default(AgentTrajectory);
            v.Size = (uint)sizeof(AgentTrajectory);
            return v;
        }

        public static AgentEvent nl_agent_event_init() { var v = default(AgentEvent); v.Size = (uint)sizeof(AgentEvent); return v; }

        public static PluginDescription nl_plugin_description_init()
        {
            var v = default(PluginDescription);
            v.Size = (uint)sizeof(PluginDescription);
            return v;
        }
    }
}
