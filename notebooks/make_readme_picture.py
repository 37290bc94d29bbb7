"""Draw the README's picture: the 2026 Earth-to-Mars porkchop of the quick start, departures from the Earth-Moon
barycentre on a 5-day grid of JPL DE421 dates (what `orbits porkchop --from EMB --to Mars --step "5 d"
--plot porkchop.png` draws).

    python notebooks/make_readme_picture.py [OUTPUT]      # default: notebooks/images/porkchop.png

The tests run it (tests/test_readme.py), so the picture the README shows is the one the code draws.
"""

import sys
from pathlib import Path

import astropy.units as u
import matplotlib

from orbits import Porkchop
from orbits.plot import porkchop, save

OUTPUT = Path(__file__).resolve().parent / "images" / "porkchop.png"


def draw(path: Path = OUTPUT) -> Path:
    """Draw the porkchop and write it to `path` (atomically); return the path."""
    matplotlib.use("Agg")
    window = Porkchop.between("EMB", "Mars", launch=("2026-09-01", "2027-01-31"),
                              arrival=("2027-06-01", "2028-03-01"), step=5 * u.day)
    figure, _ = porkchop(window)
    path.parent.mkdir(parents=True, exist_ok=True)
    save(figure, path)
    return path


if __name__ == "__main__":
    print(draw(Path(sys.argv[1]) if len(sys.argv) > 1 else OUTPUT))
