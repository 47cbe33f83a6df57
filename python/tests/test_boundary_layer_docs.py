"""docs/global_convergence.md section 6 states the boundary layer's default and its formulas as
the code has them: the default from ControllerParameters, the paper's sets at 0, and the
linear zone and the offset in the switching bound kbar_sw (the law's saturation is on
kappa_sw, dubins_switching_law.cpp), not kbar_n."""
import re

import smoothsteer
from conftest import ROOT


def section_six():
    text = (ROOT / "docs" / "global_convergence.md").read_text()
    return text.split("## 6.", 1)[1].split("\n## ", 1)[0]


def test_the_stated_default_is_the_codes():
    stated = re.search(r"The default is `epsilon = ([0-9.]+)`", section_six())
    assert stated, "section 6 does not state the default boundary layer"
    assert float(stated.group(1)) == smoothsteer.ControllerParameters().law.boundary_layer
    assert "use `epsilon = 0`" in section_six()  # paper_c1 and paper_c0


def test_the_formulas_use_the_switching_bound():
    section = section_six()
    assert "l = 4 epsilon / kbar_sw" in section
    assert "4 epsilon^2 kappa_d / kbar_sw^2" in section
    assert "/ kbar_n" not in section, "a formula of section 6 still divides by kbar_n"
