# LadderLab server image: `docker compose up` serves the app on port 8000.
FROM node:20-bookworm-slim AS frontend
WORKDIR /src
COPY . .
RUN if [ -f frontend/package.json ]; then cd frontend && npm ci --no-audit --no-fund && npm run build; fi \
    && mkdir -p backend/ladderlab/server/static

FROM python:3.11-slim
WORKDIR /app
COPY --from=frontend /src /app
RUN pip install --no-cache-dir -e .
ENV LADDERLAB_WORKSPACE=/data/workspace \
    LADDERLAB_EXAMPLES=/app/examples
VOLUME /data
EXPOSE 8000
CMD ["ladderlab", "serve", "--host", "0.0.0.0", "--port", "8000", "--allow-remote"]
