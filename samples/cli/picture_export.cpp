#include "picture_export.h"

#include "png_export.h"

namespace nl::cli {

void write_picture(const samples::Level& level, const samples::NavmeshContents& navmesh,
                   std::vector<picture::PathLayer> paths, const PictureRequest& request,
                   std::vector<picture::ScenePoint> points, std::vector<picture::ScenePlatform> platforms) {
    picture::Scene scene;
    scene.level = &level;
    scene.navmesh = &navmesh;
    scene.paths = std::move(paths);
    scene.points = std::move(points);
    scene.platforms = std::move(platforms);
    scene.title = request.title;
    picture::ViewSettings view;
    view.oblique = request.oblique;
    view.height = 0;  // as tall as the level needs
    picture::write_png(scene, view, request.path);
}

}  // namespace nl::cli
