#include "cnc_core/toolpath/Stock.h"

#include <cstddef>
#include <locale>
#include <sstream>

#include <vector>
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

namespace {
bool numbers(std::istringstream& in, std::vector<double>& out, std::size_t count) {
    double v = 0;
    while (in >> v)
        out.push_back(v);
    return in.eof() && out.size() == count;
}
}  // namespace

bool parseStock(const std::string& text, Stock& stock, std::string& error) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());  // '.' decimals whatever the desk's locale
    std::string shape;
    in >> shape;
    Stock s;
    std::vector<double> v;
    if (shape.empty() || shape == "none") {
        stock = s;
        return true;
    }
    if (shape == "block") {
        if (!numbers(in, v, 6)) {
            error = "stock block needs XMIN XMAX YMIN YMAX ZMIN ZMAX";
            return false;
        }
        for (std::size_t i = 0; i < 3; ++i) {
            s.min[i] = v[2 * i];
            s.max[i] = v[2 * i + 1];
            if (!(s.min[i] < s.max[i])) {
                error = "stock block: each minimum must be below its maximum";
                return false;
            }
        }
        s.shape = Stock::Shape::Block;
    } else if (shape == "cylinder") {
        std::string axis;
        in >> axis;
        if (axis != "X" && axis != "Y" && axis != "Z") {
            error = "stock cylinder needs its axis X, Y or Z";
            return false;
        }
        if (!numbers(in, v, 3) || !(v[0] > 0) || !(v[1] < v[2])) {
            error = "stock cylinder needs AXIS RADIUS FROM TO with radius > 0 and FROM < TO";
            return false;
        }
        s.shape = Stock::Shape::Cylinder;
        s.axis = axis[0] - 'X';
        s.radius = v[0];
        s.from = v[1];
        s.to = v[2];
    } else {
        error = "stock must be 'block ...', 'cylinder ...' or 'none'";
        return false;
    }
    stock = s;
    return true;
}

bool Stock::box(std::array<double, 3>& low, std::array<double, 3>& high) const {
    if (shape == Shape::None) return false;
    if (shape == Shape::Block) {
        low = min;
        high = max;
        return true;
    }
    for (std::size_t d = 0; d < 3; ++d) {
        const bool along = static_cast<int>(d) == axis;
        low[d] = along ? from : -radius;
        high[d] = along ? to : radius;
    }
    return true;
}

Stock stockOf(const ProcessConfig& config) {
    Stock stock;
    std::string error;
    if (!parseStock(config.stock, stock, error)) return {};  // the reader refuses it anyway
    return stock;
}

}  // namespace mtc::core
