// figure_export.cpp — the plots as figure files for "Export figures" (figure_export.h).
#include "app/figure_export.h"

#include "core/plots/figures.h"

namespace lab {

std::vector<Download> exportFigures(const Preset& a, const Preset* b, const ui::PlotSettings& settings, float pngScale,
                                    Theme theme) {
    std::vector<Download> files;
    for (FigureKind kind : kFigureKinds) {
        FigureRequest r;
        r.kind = kind;
        r.incidentDeg = a.plotIncidentDeg;
        r.scale = settings.scale;
        r.overlayDeg = settings.overlayDeg;
        r.light = settings.attenuationLight;
        r.theme = theme;
        r.component = settings.slice.component; // the Slice tab's image, in the view's palette
        r.palette = settings.palette;
        std::string error;
        std::optional<FigureResult> f = makeFigure(a, b, r, error);
        if (!f) {
            continue; // no light to draw the attenuation of
        }
        const std::string name(toString(kind));
        files.push_back({name + ".svg", figureSvg(f->figure)});
        files.push_back({name + ".png", encodePng(rasterizeFigure(f->figure, pngScale))});
        files.push_back({name + ".csv", f->csv});
    }
    return files;
}

} // namespace lab
