// The server's JSON API (apps/isopatch/view/view_server.hpp). GET /api/state: {id, summary, version}.

export async function fetchState() {
  const r = await fetch('/api/state', { cache: 'no-store' });
  if (!r.ok) throw new Error(`GET /api/state: ${r.status}`);
  return r.json();
}

// {id, summary} on success, {error: {...}} for a bad request or surface, {superseded: true} when a
// newer request took over. Throws on a network failure.
export async function requestMesh(body) {
  const r = await fetch('/api/mesh', {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
  });
  let json;
  try {
    json = await r.json();
  } catch {
    return { error: { error: `the server answered ${r.status} without JSON`, kind: 'internal' } };
  }
  if (r.status === 409) return { superseded: true };
  if (!r.ok) return { error: json };
  return json;
}
