// What a user waits for when zooming the map of a large plan with every layer on: one wheel step (the
// canvas shows its last drawing scaled) and the full redraw once the view rests. Run:
// QT_QPA_PLATFORM=offscreen build/release/bench/mcpp_canvas_benchmarks The plan: a multi-cover map of
// range(0) x range(0) bottom cells, four robots.
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"
#include "ui/MapCanvas.hpp"
#include "ui/MissionDocument.hpp"

#include <QApplication>
#include <QImage>
#include <QWheelEvent>
#include <benchmark/benchmark.h>
#include <map>
#include <memory>

using namespace mcpp;

namespace {

struct Scene {
    ui::MissionDocument document;
    std::unique_ptr<ui::MapCanvas> canvas;
    QImage screen{1600, 1000, QImage::Format_ARGB32_Premultiplied}; // what the canvas paints into
};

// The canvas painted as the screen would show it (repaint() draws nothing on the offscreen platform).
void paint(Scene& data) {
    data.canvas->render(&data.screen);
}

Scene& scene(int size) {
    static std::map<int, std::unique_ptr<Scene>> scenes;
    auto& made = scenes[size];
    if (made)
        return *made;
    made = std::make_unique<Scene>();
    PlanningProblem problem = test::randomProblem(test::multiCoverSpec(size, 4));
    problem.planner = defaultPlannerChoice("mcpp-mlct");
    auto plan = std::make_shared<const Plan>(makePlanner("mcpp-mlct")->plan(problem, {}));
    auto raster = std::make_shared<io::LoadedRaster>();
    raster->grid = problem.grid;
    io::Mission mission;
    mission.classes = problem.classes;
    for (const MapPoint& start : problem.starts)
        mission.robots.push_back({"", start, ""});
    made->document.reset(raster, mission, QString());
    made->document.setPlan(plan, made->document.currentInputs());
    made->canvas = std::make_unique<ui::MapCanvas>(&made->document);
    made->canvas->resize(1600, 1000);
    made->canvas->show();
    made->canvas->setLayers(render::MapLayers{}); // every layer on
    made->canvas->zoomToFit();
    paint(*made);
    return *made;
}

void wheel(ui::MapCanvas& canvas, int delta) {
    const QPointF cursor(800, 500);
    QWheelEvent event(cursor, canvas.mapToGlobal(cursor), QPoint(), QPoint(0, delta), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&canvas, &event);
}

// One wheel step and the repaint it causes, zooming in and out in turn around the middle of the map.
void canvas_wheelStep(benchmark::State& state) {
    Scene& data = scene(static_cast<int>(state.range(0)));
    int step = 0;
    for (auto _ : state) {
        wheel(*data.canvas, ++step % 2 == 0 ? -120 : 120);
        paint(data);
    }
    state.counters["cells"] = static_cast<double>(data.document.plan()->cells.size());
}

// A full redraw: after a change of what is shown (here a layer switched), and once the view rests after
// zoom or pan steps. Before the canvas kept its drawing, every wheel step cost this.
void canvas_redrawAfterChange(benchmark::State& state) {
    Scene& data = scene(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        data.canvas->setLayers(render::MapLayers{});
        paint(data);
    }
}

} // namespace

BENCHMARK(canvas_redrawAfterChange)->Arg(1024)->Arg(1900)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(canvas_wheelStep)->Arg(1024)->Arg(1900)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
