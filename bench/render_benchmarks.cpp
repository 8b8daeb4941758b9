// What a user waits for on the map: one repaint of a large plan, whole map in view and zoomed in to a few
// hundred metres. Run: build/release/bench/mcpp_render_benchmarks
// The plan: 1024 x 1024 bottom cells of three land covers (about a million cells), four robots.
#include "core/planners/PlannerRegistry.hpp"
#include "render/PlanRenderer.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <benchmark/benchmark.h>
#include <memory>

using namespace mcpp;

namespace {

struct Scene {
    PlanningProblem problem;
    Plan plan;
};

const Scene& scene() {
    static const std::unique_ptr<Scene> made = [] {
        auto result = std::make_unique<Scene>();
        result->problem = test::randomProblem(test::multiCoverSpec(1024, 4));
        result->problem.planner = defaultPlannerChoice("mcpp-mlct");
        result->plan = makePlanner("mcpp-mlct")->plan(result->problem, {});
        return result;
    }();
    return *made;
}

// Preparing the renderer for a new plan: what the canvas does once after planning.
void renderer_setPlan(benchmark::State& state) {
    const Scene& data = scene();
    for (auto _ : state) {
        render::PlanRenderer renderer;
        renderer.setMap(&data.problem.grid, &data.problem.classes);
        renderer.setPlan(&data.plan);
        benchmark::DoNotOptimize(renderer);
    }
    state.counters["cells"] = static_cast<double>(data.plan.cells.size());
}

// One repaint of a 1600 x 1000 view; range(0) = view width in metres (0: the whole map).
void renderer_paint(benchmark::State& state) {
    const Scene& data = scene();
    render::PlanRenderer renderer;
    renderer.setMap(&data.problem.grid, &data.problem.classes);
    renderer.setPlan(&data.plan);
    QImage image(1600, 1000, QImage::Format_ARGB32_Premultiplied);
    const ClassGrid& grid = data.problem.grid;
    QTransform transform = render::PlanRenderer::fitTransform(grid, QSizeF(image.size()));
    if (state.range(0) > 0) {
        // Zoomed in around the map's centre.
        const double scale = 1600.0 / static_cast<double>(state.range(0));
        const double centreX = grid.originX + grid.width() / 2.0;
        const double centreY = grid.originY - grid.height() / 2.0;
        transform = QTransform(scale, 0.0, 0.0, -scale, 800.0 - centreX * scale, 500.0 + centreY * scale);
    }
    for (auto _ : state) {
        image.fill(Qt::white);
        QPainter painter(&image);
        renderer.paint(painter, transform, QRectF(0, 0, 1600, 1000));
    }
}

// The whole map with one layer on; range(0): 0 land cover, 1 regions, 2 cells, 3 paths, 4 unreachable.
void renderer_paintOneLayer(benchmark::State& state) {
    const Scene& data = scene();
    render::PlanRenderer renderer;
    renderer.setMap(&data.problem.grid, &data.problem.classes);
    renderer.setPlan(&data.plan);
    render::MapLayers layers{false, false, false, false, false, false};
    const auto layer = state.range(0);
    layers.landCover = layer == 0;
    layers.regions = layer == 1;
    layers.quadTree = layer == 2;
    layers.paths = layer == 3;
    layers.unreachable = layer == 4;
    renderer.setLayers(layers);
    QImage image(1600, 1000, QImage::Format_ARGB32_Premultiplied);
    const QTransform transform = render::PlanRenderer::fitTransform(data.problem.grid, QSizeF(image.size()));
    for (auto _ : state) {
        image.fill(Qt::white);
        QPainter painter(&image);
        renderer.paint(painter, transform, QRectF(0, 0, 1600, 1000));
    }
}

BENCHMARK(renderer_setPlan)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(renderer_paintOneLayer)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);
BENCHMARK(renderer_paint)->Arg(0)->Arg(2000)->Arg(200)->Unit(benchmark::kMillisecond)->MinTime(2.0);

} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication application(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
