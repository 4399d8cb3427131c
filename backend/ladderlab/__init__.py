"""LadderLab: IEC 61131-3 LD/FBD/ST editor and scan-cycle simulator."""

__version__ = "0.1.0"
