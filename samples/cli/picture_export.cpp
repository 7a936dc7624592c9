#include "picture_export.h"

#include "drop_runs.h"
#include "island_colors.h"
#include "png_export.h"

namespace nl::cli {

std::string write_picture(const samples::Level& level, const samples::NavmeshContents& navmesh,
                          std::vector<picture::PathLayer> paths, const PictureRequest& request,
                          std::vector<picture::ScenePoint> points, std::vector<picture::ScenePlatform> platforms) {
    picture::Scene scene;
    scene.level = &level;
    scene.navmesh = &navmesh;
    scene.islands = request.islands ? &*request.islands : nullptr;
    scene.paths = std::move(paths);
    scene.points = std::move(points);
    scene.platforms = std::move(platforms);
    scene.title = request.title;
    picture::ViewSettings view;
    view.oblique = request.oblique;
    view.layers.link_numbers = request.link_numbers;
    view.layers.roofs = request.roofs;
    view.height = 0;  // as tall as the level needs
    picture::write_png(scene, view, request.path);
    std::string counted = "drops: " + picture::drop_summary(navmesh.links);
    if (request.islands) counted += "; " + picture::islands_text(*request.islands);
    return counted;
}

}  // namespace nl::cli
