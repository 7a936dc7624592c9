// The CLI's pictures: the scene of a generated level (its paths, points and moving platforms) written
// as a PNG by samples/sdl.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "level.h"
#include "navmesh_contents.h"
#include "scene.h"

namespace nl::cli {

struct PictureRequest {
    std::string path;
    std::string title;
    bool oblique = false;
    bool link_numbers = false;  // --link-numbers: each link's index, as in LINKS.json and navlink path
    bool roofs = false;         // --roofs: draw the level whole, roofs over the navmesh included
    std::optional<picture::SceneIslands> islands;  // navmesh polygons coloured by this body's islands
};

// Writes the picture; returns what it counted that the text output may say: "drops: 141 (38
// arrows); 5 islands for the walker".
std::string write_picture(const samples::Level& level, const samples::NavmeshContents& navmesh,
                          std::vector<picture::PathLayer> paths, const PictureRequest& request,
                          std::vector<picture::ScenePoint> points = {},
                          std::vector<picture::ScenePlatform> platforms = {});

}  // namespace nl::cli
