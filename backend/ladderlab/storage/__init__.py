"""Project storage: workspace folders, single-file projects, and ST source files."""

from .errors import (
    AlreadyExistsError,
    ConflictError,
    InvalidNameError,
    NotFoundError,
    ProjectLoadError,
    StorageError,
    StorageFullError,
)
from .load import load_project_path
from .workspace import ProjectInfo, StoredProject, Workspace

__all__ = [
    "AlreadyExistsError",
    "ConflictError",
    "InvalidNameError",
    "NotFoundError",
    "ProjectInfo",
    "ProjectLoadError",
    "StorageError",
    "StorageFullError",
    "StoredProject",
    "Workspace",
    "load_project_path",
]
