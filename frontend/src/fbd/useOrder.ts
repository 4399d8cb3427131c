// The execution order of every network, as the backend's lowering computes it (POST
// /api/fbd/order), fetched debounced after edits and only for networks whose content changed.
import { useEffect, useRef, useState } from "react";
import { http, unwrap } from "../api/client";
import type { FbdOrder } from "../generated/api";
import { networksOf, type FbdBody, type FbdNetwork } from "./model";

export const ORDER_DEBOUNCE_MS = 250;

export const fetchOrder = (network: FbdNetwork): Promise<FbdOrder> =>
  unwrap(http.POST("/api/fbd/order", { body: network }));

/** A CFC chart's execution order (its order list decides, CFC-02). */
export const fetchChartOrder = (network: FbdNetwork): Promise<FbdOrder> =>
  unwrap(http.POST("/api/fbd/order", { body: network, params: { query: { chart: true } } }));

/** Network id -> node ids in execution order, for the networks in `only` (missing until the server has answered). */
export function useEvaluationOrder(
  body: FbdBody,
  fetcher: (network: FbdNetwork) => Promise<FbdOrder> = fetchOrder,
  only?: ReadonlySet<string>,
): ReadonlyMap<string, readonly string[]> {
  const [orders, setOrders] = useState<ReadonlyMap<string, readonly string[]>>(new Map());
  // Content text -> its order, so undo and switching back cost no request.
  const cache = useRef(new Map<string, readonly string[]>());
  useEffect(() => {
    let cancelled = false;
    const timer = setTimeout(() => {
      const networks = networksOf(body).filter((n) => !only || only.has(n.id));
      void Promise.all(
        networks.map(async (network): Promise<[string, readonly string[] | null]> => {
          const key = JSON.stringify(network);
          const known = cache.current.get(key);
          if (known) return [network.id, known];
          try {
            const { order } = await fetcher(network);
            cache.current.set(key, order);
            return [network.id, order];
          } catch {
            return [network.id, null]; // no badges for this network until the next edit
          }
        }),
      ).then((pairs) => {
        if (!cancelled) setOrders(new Map(pairs.filter((p): p is [string, readonly string[]] => p[1] !== null)));
      });
    }, ORDER_DEBOUNCE_MS);
    return () => {
      cancelled = true;
      clearTimeout(timer);
    };
  }, [body, fetcher, only]);
  return orders;
}
