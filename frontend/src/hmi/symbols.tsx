// Plant symbols drawn in a 100 x 100 box (stretched to the widget for walls, doors and belts): their
// look shows a state, `on` (running, open, heating, sounding) or `amount` (0..1: a cylinder's stroke,
// a door's opening). Turning and moving parts are CSS animations (hmi.css), which cost no renders.
import type { ReactNode } from "react";
import type { SymbolShape } from "./model";

export interface SymbolLook {
  shape: SymbolShape;
  on: boolean;
  amount: number;
  color: string;
  fault: boolean;
}

const STRETCHED: ReadonlySet<SymbolShape> = new Set(["wall", "door", "conveyor", "box", "car", "cylinder"]);

/** How the symbol's 100 x 100 drawing fills the widget. */
export const aspectOf = (shape: SymbolShape): string => (STRETCHED.has(shape) ? "none" : "xMidYMid meet");

const ACTIVE = "#43a047";
const IDLE = "#9e9e9e";
const FAULT = "#e53935";

export function SymbolDrawing({ shape, on, amount, color, fault }: SymbolLook): ReactNode {
  const stroke = fault ? FAULT : "#37474f";
  const fill = on ? ACTIVE : IDLE;
  switch (shape) {
    case "motor":
    case "pump":
    case "fan":
      return (
        <g stroke={stroke} strokeWidth={fault ? 5 : 3}>
          <circle cx={50} cy={50} r={44} fill={fault ? "#ffcdd2" : "#eceff1"} />
          {shape === "pump" ? <path d="M50 6 L94 50 L50 94" fill="none" /> : null}
          <g className={on ? "hmi-spin" : undefined}>
            {shape === "fan" ? (
              [0, 120, 240].map((a) => (
                <ellipse key={a} cx={50} cy={28} rx={10} ry={22} fill={fill} transform={`rotate(${a} 50 50)`} />
              ))
            ) : (
              <>
                <circle cx={50} cy={50} r={26} fill={fill} />
                <line x1={50} y1={24} x2={50} y2={76} stroke="#fff" strokeWidth={6} />
              </>
            )}
          </g>
          {shape === "motor" ? (
            <text x={50} y={58} textAnchor="middle" fontSize={22} fill="#fff" stroke="none" fontWeight="bold">
              M
            </text>
          ) : null}
        </g>
      );
    case "valve":
      return (
        <g stroke={stroke} strokeWidth={3} fill={fill}>
          <path d="M6 24 L50 50 L6 76 Z M94 24 L50 50 L94 76 Z" />
          <line x1={50} y1={50} x2={50} y2={14} />
          <rect x={36} y={4} width={28} height={12} />
        </g>
      );
    case "heater":
      return (
        <g stroke={stroke} strokeWidth={3}>
          <rect x={6} y={20} width={88} height={60} rx={6} fill={on ? "#ff7043" : "#cfd8dc"} />
          <path
            d="M14 50 q8 -20 16 0 t16 0 t16 0 t16 0 t16 0"
            fill="none"
            stroke={on ? "#ffeb3b" : "#78909c"}
            strokeWidth={5}
            className={on ? "hmi-glow" : undefined}
          />
        </g>
      );
    case "conveyor":
      return (
        <g stroke={stroke} strokeWidth={2}>
          <rect x={0} y={20} width={100} height={60} rx={30} fill="#cfd8dc" />
          <line
            x1={10}
            y1={20}
            x2={90}
            y2={20}
            stroke="#263238"
            strokeWidth={6}
            strokeDasharray="8 6"
            className={on ? "hmi-belt" : undefined}
          />
          <circle cx={12} cy={50} r={8} fill={fill} />
          <circle cx={88} cy={50} r={8} fill={fill} />
        </g>
      );
    case "cylinder": {
      const rod = 6 + amount * 60;
      return (
        <g stroke={stroke} strokeWidth={2}>
          <rect x={20} y={0} width={60} height={34} fill={fault ? "#ffcdd2" : "#b0bec5"} />
          <rect x={44} y={34} width={12} height={rod} fill="#78909c" />
          <rect x={14} y={34 + rod} width={72} height={8} fill={color} />
        </g>
      );
    }
    case "door": {
      const closed = 100 * (1 - amount);
      return (
        <g stroke={stroke} strokeWidth={1}>
          <rect x={0} y={0} width={100} height={100} fill="#fafafa" />
          <rect x={0} y={0} width={100} height={closed} fill={color} />
          {Array.from({ length: Math.floor(closed / 12.5) }, (_, i) => (
            <line key={i} x1={0} x2={100} y1={closed - 12.5 * (i + 1)} y2={closed - 12.5 * (i + 1)} stroke="#263238" />
          ))}
        </g>
      );
    }
    case "siren":
      return (
        <g stroke={stroke} strokeWidth={3}>
          <path d="M20 80 L20 45 A30 30 0 0 1 80 45 L80 80 Z" fill={on ? "#e53935" : "#bdbdbd"} />
          <rect x={10} y={80} width={80} height={12} fill="#616161" />
          {on ? (
            <g className="hmi-blink" fill="none" stroke="#e53935">
              <path d="M6 30 A50 50 0 0 1 30 6" />
              <path d="M94 30 A50 50 0 0 0 70 6" />
            </g>
          ) : null}
        </g>
      );
    case "box":
      return <rect x={2} y={2} width={96} height={96} fill={color} stroke="#3e2723" strokeWidth={3} />;
    case "person":
      return (
        <g fill={color} stroke="none">
          <circle cx={50} cy={16} r={13} />
          <path d="M34 32 H66 L62 66 H38 Z" />
          <path d="M38 64 L30 98 H42 L50 70 L58 98 H70 L62 64 Z" />
        </g>
      );
    case "car":
      return (
        <g stroke="#263238" strokeWidth={2}>
          <path d="M4 70 V50 L20 48 L32 22 H70 L84 48 L96 52 V70 Z" fill={color} />
          <rect x={36} y={28} width={30} height={18} fill="#e3f2fd" />
          <circle cx={24} cy={72} r={12} fill="#263238" />
          <circle cx={76} cy={72} r={12} fill="#263238" />
        </g>
      );
    case "wall":
      return <rect x={0} y={0} width={100} height={100} fill={color} />;
  }
}
