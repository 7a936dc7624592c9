/*
 * Not a NavLink header. A declaration navlink-abi-hostile-test has no case for, read with the
 * public headers by the ctest abi_hostile_coverage_selftest: the coverage check must name the
 * function, and each case its parameters and fields call for, as missing.
 */
typedef struct nl_hostile_selftest_def {
    uint32_t size;
    float x;
    const float* points;
    uint32_t point_count;
    nl_navmesh_id navmesh;
} nl_hostile_selftest_def;

NL_API nl_status nl_hostile_selftest(nl_world* world, const nl_hostile_selftest_def* def, uint32_t* out_count);
