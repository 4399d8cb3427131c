"""server package."""

from pathlib import Path

#: The built browser app (``npm run build`` writes it); here, not in app.py, so ``ladderlab doc`` finds the print view
#: without importing FastAPI.
STATIC_DIR = Path(__file__).parent / "static"
