// The FBD editor's wire (issue 28): drawn along the orthogonal route of ../route.ts around the nodes of
// its network (the canvas's measured node boxes), with its arrow and, online, its value at the middle.
import { BaseEdge, useStore, type EdgeProps } from "@xyflow/react";
import { useMemo } from "react";
import { pathOf, route, type Box, type Point } from "../route";

/** The point halfway along the wire, for its label. */
function middle(points: readonly Point[]): Point {
  const lengths = points.slice(1).map((p, i) => Math.abs(p.x - points[i]!.x) + Math.abs(p.y - points[i]!.y));
  let left = lengths.reduce((a, b) => a + b, 0) / 2;
  for (let i = 0; i < lengths.length; i += 1) {
    const a = points[i]!;
    const b = points[i + 1]!;
    if (left <= lengths[i]!) {
      const t = lengths[i] ? left / lengths[i]! : 0;
      return { x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t };
    }
    left -= lengths[i]!;
  }
  return points[0]!;
}

export function OrthogonalEdge(props: EdgeProps) {
  const { sourceX, sourceY, targetX, targetY } = props;
  const nodes = useStore((s) => s.nodeLookup);
  const points = useMemo(() => {
    const boxes: Box[] = [];
    for (const node of nodes.values()) {
      const { width, height } = node.measured;
      if (width && height)
        boxes.push({ x: node.internals.positionAbsolute.x, y: node.internals.positionAbsolute.y, width, height });
    }
    return route({ x: sourceX, y: sourceY }, { x: targetX, y: targetY }, boxes);
  }, [nodes, sourceX, sourceY, targetX, targetY]);
  const label = middle(points);
  return (
    <BaseEdge
      id={props.id}
      path={pathOf(points)}
      markerEnd={props.markerEnd}
      style={props.style}
      label={props.label}
      labelX={label.x}
      labelY={label.y}
      labelStyle={props.labelStyle}
      labelShowBg={props.labelShowBg}
      labelBgStyle={props.labelBgStyle}
      labelBgPadding={props.labelBgPadding}
      labelBgBorderRadius={props.labelBgBorderRadius}
      interactionWidth={props.interactionWidth}
    />
  );
}
