// The CLI's pictures: the scene of a generated level (its paths, points and moving platforms) written
// as a PNG by samples/sdl.
#pragma once

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
};

void write_picture(const samples::Level& level, const samples::NavmeshContents& navmesh,
                   std::vector<picture::PathLayer> paths, const PictureRequest& request,
                   std::vector<picture::ScenePoint> points = {}, std::vector<picture::ScenePlatform> platforms = {});

}  // namespace nl::cli
