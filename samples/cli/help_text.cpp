#include "help_text.h"

namespace nl::cli {

// How LEVEL.obj is given, for generate, bake and path.
#define NL_LEVEL_FRAME_OPTIONS_HELP                                                                           \
    "  --clockwise           LEVEL's fronts are wound clockwise (Godot's convention; NL_MESH_CLOCKWISE)\n"    \
    "  --units U             LEVEL's unit: m, cm, mm, km, in, ft, or the metres in one unit (0.01 for\n"      \
    "                        centimetres); nl_mesh_def.metres_per_unit. Without it LEVEL is read as metres\n" \
    "                        and a size that suggests other units is warned about on stderr\n"                \
    "  --up y|z              LEVEL's up axis (z: Blender's, 3ds Max's own frame; nl_mesh_def.up_axis).\n"     \
    "                        Without it y is up, and a level that looks z up is warned about on stderr;\n"    \
    "                        so is one that looks wound clockwise without --clockwise\n"

// The picture options of generate, bake, path and demo, and what their pictures show.
#define NL_PICTURE_OPTIONS_HELP                                                                          \
    "  --link-numbers        number each link in the picture by its index in LINKS.json, as navlink\n"   \
    "                        path prints it (#N)\n"                                                      \
    "  --roofs               draw the level whole; by default a surface more than 1.5 m above the\n"     \
    "                        navmesh under it (a roof, a ceiling) is cut away, so the floor shows\n"     \
    "\n"                                                                                                 \
    "The picture has a grid labelled in metres (x across, z down) to read --from and --to off, the\n"    \
    "navmesh coloured by the islands of the body it is about (the polygons it can walk and take links\n" \
    "between), one arrow per ledge of drops (the legend counts both), and a start or goal off the map\n" \
    "marked at its edge with an arrow its way.\n"

const char* const kMainHelp =
    "usage: navlink COMMAND [ARGUMENTS]\n"
    "\n"
    "NavLink: navmeshes with generated jump and drop links, and paths for agents that can take them.\n"
    "\n"
    "commands:\n"
    "  demo    generate the default level, generate its links, plan one route for three agents\n"
    "          (a walker, a short jumper, a long jumper who may drop); writes demo.png, demo.links.json\n"
    "  simulate    the same three bodies as agents that walk, jump and drop to the goal; prints when\n"
    "          and where each arrived; writes simulate.png with their tracks. --platforms: passengers\n"
    "          ride a shuttle, a turning disc and a lift beside the level; writes platforms.png\n"
    "  generate    build a level's navmesh and generate its jump and drop links into a JSON file\n"
    "  bake    the same, written with the navmesh as one baked navmesh file (.nlnav) to load at run time\n"
    "  path    plan a path over a level's navmesh and links, or over a baked file, and print its segments\n"
    "  info    say what a baked navmesh file holds and what it was made for\n"
    "  level   write the generated default level as an OBJ file\n"
    "\n"
    "`navlink COMMAND --help` describes a command; `navlink --version` prints the tool's and the\n"
    "library's versions. Errors are one line on stderr and exit status 2.\n";

const char* const kGenerateHelp =
    "usage: navlink generate LEVEL.obj --out LINKS.json [--navmesh NAVMESH.obj] [--agent AGENT.json]\n"
    "                    [--settings GEN.json] [--plugin PLUGIN.so] [--png VIEW.png] [--oblique]\n"
    "                    [--link-numbers] [--roofs]\n"
    "                    [--clockwise] [--units U] [--up y|z]\n"
    "\n"
    "Builds LEVEL's navmesh with the built-in Recast builder (or takes NAVMESH.obj: convex polygons, Y up),\n"
    "generates jump and drop links against the level geometry, writes them to LINKS.json and prints the\n"
    "generation report: links by kind, rejections by reason, milliseconds per stage.\n"
    "\n"
    "  --out LINKS.json      where the links go (schema \"navlink-links\" 1)\n" NL_LEVEL_FRAME_OPTIONS_HELP
    "  --navmesh NAVMESH.obj use this navmesh instead of building one\n"
    "  --agent AGENT.json    the body the navmesh is built for; default Recast's (radius 0.6, height 2,\n"
    "                        max_climb 0.9, max_slope 45). Keys: name, radius, height, max_climb,\n"
    "                        max_slope. Capabilities (max_jump_distance...) are refused here: they\n"
    "                        choose links when a path is planned (navlink path --agent)\n"
    "  --settings GEN.json   link generator settings (docs/link-generation.md), e.g.\n"
    "                        {\"max_jump_gap\": 6, \"recast\": {\"cell_size\": 0.2}, \"plugins\": {\"climb\": {}}}\n"
    "                        \"plugins\" holds each loaded link-kind plugin's settings by its kind name\n"
    "  --plugin PLUGIN.so    load a link-kind plugin library (nl_plugin_load): its links are generated\n"
    "                        with the others; settings for a kind no loaded plugin provides are refused\n"
    "  --png VIEW.png        also draw the level, navmesh, outline and links (islands for navlink path's\n"
    "                        default body)\n"
    "  --oblique             draw the picture from an angle instead of straight down\n" NL_PICTURE_OPTIONS_HELP;

const char* const kBakeHelp =
    "usage: navlink bake LEVEL.obj --out NAVMESH.nlnav [--navmesh NAVMESH.obj] [--agent AGENT.json]\n"
    "                    [--settings GEN.json] [--plugin PLUGIN.so] [--png VIEW.png] [--oblique]\n"
    "                    [--link-numbers] [--roofs]\n"
    "                    [--clockwise] [--units U] [--up y|z]\n"
    "       navlink bake LEVEL.obj --tile-size N --out DIR [same options]\n"
    "\n"
    "As navlink generate, but writes the navmesh, its links and what they were made for (the body, the\n"
    "builder and its settings, the level's hash, the link settings) as one baked navmesh file: compact,\n"
    "checked, loaded with no rebuild by nl_navmesh_load_file or navlink path NAVMESH.nlnav.\n"
    "(navlink generate still writes the links alone as JSON.)\n"
    "With --tile-size, the navmesh is built in tiles of N cells and written as one file per tile (its\n"
    "polygons and the links that start on it, nl_navmesh_save_tile) and DIR/index.json (each tile's\n"
    "file and content hash): a game streams the tiles it needs (nl_navmesh_load_file for the first,\n"
    "nl_navmesh_add_tile_file for the others, in any order). A bake into a DIR that holds one keeps the\n"
    "files of tiles whose content hash is unchanged, and says how many it wrote and kept.\n"
    "\n"
    "  --out NAVMESH.nlnav   where the file goes (written whole or not at all)\n"
    "  --tile-size N         cells per tile side (16 to 4096; 32 to 128 suit most levels); --out is a\n"
    "                        folder then (made if needed)\n"
    "  other options         as navlink generate\n";

const char* const kInfoHelp =
    "usage: navlink info NAVMESH.nlnav [--json]\n"
    "       navlink info DIR [--json]\n"
    "\n"
    "Prints what a baked navmesh file holds (polygons, vertices, links, format version) and what it was\n"
    "made for: the body, the builder and its settings, the hash of the level it was built from, the\n"
    "link generation settings. The file is checked whole; a damaged one is refused with the reason.\n"
    "A tile's file also says its tile, grid and content hash; a tile bake's folder (navlink bake\n"
    "--tile-size) lists every tile with its file, polygons, links, bytes and content hash, each file\n"
    "checked against the index.\n"
    "\n"
    "  --json                print only what it was made for, as JSON\n";

const char* const kPathHelp =
    "usage: navlink path LEVEL.obj --from X,Y,Z --to X,Y,Z [--links LINKS.json] [--agent AGENT.json]\n"
    "                    [--search X,Y,Z] [--navmesh NAVMESH.obj] [--settings GEN.json] [--json]\n"
    "                    [--png VIEW.png] [--oblique] [--link-numbers] [--roofs]\n"
    "                    [--clockwise] [--units U] [--up y|z]\n"
    "                    [--any-body]\n"
    "       navlink path NAVMESH.nlnav --from X,Y,Z --to X,Y,Z [--links LINKS.json] [--agent AGENT.json]\n"
    "                    [--search X,Y,Z] [--json] [--any-body]\n"
    "       navlink path DIR --from X,Y,Z --to X,Y,Z [same options as NAVMESH.nlnav]\n"
    "\n"
    "Plans a path from --from to --to for the agent over LEVEL's navmesh and the links of LINKS.json (from\n"
    "navlink generate with the same level, agent and settings; without --links the navmesh is walked\n"
    "alone), and prints its points: how each segment is travelled (walk, jump, drop), the link taken, and\n"
    "its straight length; and the length walked along the surface (with --json: \"length\", beside\n"
    "\"straight_length\" between the points). A path that does not reach the goal says how far from it\n"
    "it ends; an end off the navmesh says where the navmesh is nearest. Over a baked NAVMESH.nlnav\n"
    "(navlink bake), nothing is built: the file's navmesh and links are planned over as they are\n"
    "(--links replaces its links); so are a tile bake's (DIR from navlink bake --tile-size), its\n"
    "tiles loaded one by one.\n"
    "\n"
    "  --links LINKS.json    the links to plan with (navlink generate)\n"
    "  --agent AGENT.json    the body and what it can take: radius, height, max_climb, max_slope,\n"
    "                        max_jump_distance, max_jump_height, max_drop_height, abilities (default:\n"
    "                        Recast's body, jumps up to 4 m across and 1.5 m up, drops up to 5 m)\n"
    "  --search X,Y,Z        half extents of the box --from and --to are looked up in on the navmesh,\n"
    "                        metres (default 2,4,2)\n"
    "  --navmesh NAVMESH.obj the navmesh as polygons, instead of building one from LEVEL with Recast\n"
    "  --settings GEN.json   the settings file of navlink generate: its \"recast\" part builds the navmesh\n"
    "                        from LEVEL\n"
    "  --any-body            load LINKS.json even when its links were generated for another body than\n"
    "                        the navmesh's (NL_LINKS_LOAD_ANY_BODY): a warning instead of a refusal\n"
    "  --json                print the path as a JSON object instead of text\n" NL_LEVEL_FRAME_OPTIONS_HELP
    "  --png VIEW.png        also draw the path over the level (islands for the agent)\n"
    "  --oblique             draw the picture from an angle instead of straight down\n" NL_PICTURE_OPTIONS_HELP
    "\n"
    "Exit status: 0 when the path reaches the goal, 1 when it does not (partial, no path, start or goal\n"
    "off the navmesh), 2 on an error.\n";

const char* const kDemoHelp =
    "usage: navlink demo [--seed N] [--out-dir DIR] [--oblique] [--link-numbers] [--roofs]\n"
    "\n"
    "Generates the default level (seed 1 unless --seed), builds its navmesh, generates its links, and plans\n"
    "the same start and goal for three agents: a walker (no jumps, no drops), a short jumper (gaps of\n"
    "2 m, 1 m up, no drops) and a long jumper who may drop (gaps of 3.5 m, 1.5 m up, drops of 4 m).\n"
    "Prints a table of their routes and writes demo.png and demo.links.json (in DIR, default '.'; made\n"
    "if missing, and checked before any work). The picture's islands are the walker's.\n"
    "\n"
    "  --oblique             draw the picture from an angle instead of straight down\n" NL_PICTURE_OPTIONS_HELP;

const char* const kSimulateHelp =
    "usage: navlink simulate [--seed N] [--out-dir DIR] [--hz N] [--seconds N] [--oblique] [--platforms]\n"
    "       navlink simulate LEVEL.obj --from X,Y,Z --to X,Y,Z [--agent AGENT.json] [--links LINKS.json]\n"
    "                    [--settings GEN.json] [--clockwise] [--units U] [--up y|z] [--out-dir DIR] [--hz N]\n"
    "                    [--seconds N] [--oblique] [--any-body]\n"
    "\n"
    "With LEVEL.obj: builds its navmesh and generates its links (or loads --links), then sends one agent\n"
    "of AGENT.json's body and capabilities (without --agent, the demo's walker, short jumper and long\n"
    "jumper) from --from to --to, as below. --clockwise, --units and --up say how LEVEL is given, as for\n"
    "navlink generate.\n"
    "\n"
    "Without LEVEL.obj:\n"
    "Generates the default level and its links as navlink demo does, then adds the demo's three bodies as\n"
    "agents at the start (nl_agent_add), sends them to the goal and steps the world N times a second\n"
    "(--hz, default 60) until every agent has arrived or failed, or --seconds (default 120) have passed.\n"
    "Prints each take-off (jump or drop, from where to where, how long in the air), each wait at a\n"
    "take-off and each arrival as it happens, then a table: outcome, time, position, distance to the\n"
    "goal, metres travelled, links taken, seconds waited.\n"
    "Writes simulate.png (in DIR, default '.'; made if missing): the level and the track each agent\n"
    "really took.\n"
    "\n"
    "--platforms: beside the level, a shuttle crosses a chasm, a disc turns in a pit and a lift climbs to\n"
    "an upper floor, each on its timetable (moved before every step, nl_mesh_set_transform), with\n"
    "gangways (cross links) placed where each docks. Four passengers leave the apron: across the\n"
    "chasm, onto the disc, past the disc, up to the upper floor. They wait at a gangway until its\n"
    "platform is there, ride, and get off. Writes platforms.png: the tracks and the platforms.\n"
    "\n"
    "Exit status: 0 when every agent arrived, 1 when one did not, 2 on an error.\n";

const char* const kLevelHelp =
    "usage: navlink level --out LEVEL.obj [--seed N]\n"
    "\n"
    "Writes the generated default level (seed 1 unless --seed) as a Wavefront OBJ file: platforms at\n"
    "several heights across gaps of several widths, ledges, stairs, a wall, a low ceiling, a corridor.\n";

}  // namespace nl::cli
