"""Continuous function chart (CFC, issue 26): FBD placed freely on one chart, without networks (CFC-01).

The chart is stored as an ``FbdBody`` with exactly one network, so everything that reads FBD (wires,
connectors, pin flags, places, cross-references, renames) reads a chart unchanged. What differs is the
execution order (CFC-02): the chart's ``order`` lists its executed elements - blocks, outputs, jumps and
returns - and an element's execution order number is its position there plus one. That order is the
order the scan runs them in, whatever the wiring: a wire whose consumer runs before its producer carries
the producer's value of the previous scan (feedback). Elements the list leaves out run after the listed
ones, in data-flow order (docs/diagrams.md, "CFC").
"""

from __future__ import annotations

from pydantic import Field, field_validator

from .fbd import FbdBody, FbdNetwork

#: The id of a new chart's one network (any id is accepted on load).
CHART_ID = "chart"


class CfcBody(FbdBody):
    """A CFC POU's body: ``networks`` holds exactly one network, the chart."""

    networks: list[FbdNetwork] = Field(default_factory=lambda: [FbdNetwork(id=CHART_ID)], description="The chart.")

    @field_validator("networks")
    @classmethod
    def _one_chart(cls, networks: list[FbdNetwork]) -> list[FbdNetwork]:
        if not networks:
            return [FbdNetwork(id=CHART_ID)]
        if len(networks) > 1:
            raise ValueError(
                f"a CFC body is one chart without networks (CFC-01); this one has {len(networks)}: "
                "put their elements on one chart, or make the POU FBD"
            )
        return networks

    @property
    def chart(self) -> FbdNetwork:
        return self.networks[0]
