"""The whole-impact grid (scenes/grids/whole-impacts.toml) with other levels: what
scripts/window-vs-whole.py and scripts/rigid-limit.py run."""
import pathlib
import re

GRID = pathlib.Path(__file__).resolve().parent.parent / "scenes/grids/whole-impacts.toml"


def with_levels(title, er, rls, ke, density):
    """The grid file's text with its title and its four axes' levels replaced (each a string of
    comma-separated numbers)."""
    text = re.sub(r'(?m)^title = .*$', f'title = "{title}"', GRID.read_text())
    for key, values in (("ER", er), ("RLS", rls), ("KE", ke), ("density_ratio", density)):
        text = re.sub(rf'(?m)^{key} = \[.*$', f"{key} = [{values}]", text)
    return text
