// fairness 5.1 pass: the list walked from its end, a hit kept only when strictly closer
// The interval's max is moved just below each hit's t, so an equal t found later (an earlier
// surface) is refused: the later surface still wins a tie.
// @helpers
#include <cmath>
// @body
    bool found = false;
    for (auto it = surfaces_.rbegin(); it != surfaces_.rend(); ++it)
        if (it->hit(ray, interval, rec)) {
            found = true;
            interval.max = std::nextafter(rec.t, -kInfinity);
        }
    return found;
