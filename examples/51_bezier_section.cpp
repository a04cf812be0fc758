// Lesson 51: a Bezier curve used as a function z(r) (tokai1994 §3.2, Table 1).
// Figures: paper_figures/tokai1994/fig11_bezier_curve.cpp,
//   paper_figures/tokai1994/fig13_15_sections.cpp.
//
// A cubic Bezier curve P(t) = (r(t), z(t)) (eq. 2) is given by 4 control points. To use it as
// the cross-section of a scale we need z for a given r, i.e. the t with r(t) = r. That only
// works when r(t) never decreases: validate_section checks it exactly, and section_at_r then
// finds t by Newton steps kept inside a bisection bracket.
//
// Build and run:  make examples   (prints the three Table 1 sections)
#include <cstdio>
#include <initializer_list>

#include "shitsukan/leather/relief.hpp"

using namespace shitsukan;

int main() {
    for (Table1Section which :
         {Table1Section::convex, Table1Section::concave, Table1Section::two_segment}) {
        BezierChain section = table1_section(which);
        Status s = validate_section(section);
        std::printf("%s: %s\n   r     t      z      dz/dr\n", table1_section_name(which),
                    s.message());
        for (int k = 0; k <= 10; ++k) {
            float r = 0.1f * float(k);
            SectionSample q = section_at_r(section, r);  // z(r), and eq. (3) at that t
            // Past the last control point section_at_r clamps to the end point (with the
            // end's eq. (3) tangent); the relief continues flat there, the groove floor.
            bool floor = r > section_r_last(section);
            float slope = !floor && q.dr != 0.0f ? q.dz / q.dr : 0.0f;
            std::printf("  %.1f  %.3f  %.4f  %+.3f%s\n", double(r), double(q.t), double(q.z),
                        double(slope), floor ? "  (groove floor)" : "");
        }
    }
    // A section that turns back in r is refused with the reason.
    BezierChain bad = table1_section(Table1Section::convex);
    bad.segments[0].p[3].x = 0.3f;
    std::printf("r3 = 0.3 instead of 0.92: %s\n", validate_section(bad).message());
    return 0;
}
