// The server's JSON API (src/serve/route.cpp), as the page uses it.

export class ApiError extends Error {}

async function json(response) {
  let body = null;
  try {
    body = await response.json();
  } catch {
    body = null;
  }
  if (!response.ok) throw new ApiError(body?.error ?? `the server answered ${response.status} ${response.statusText}`);
  return body;
}

async function call(method, url, body) {
  let response;
  try {
    response = await fetch(url, {
      method,
      cache: 'no-store',
      headers: body === undefined ? {} : { 'Content-Type': 'application/json' },
      body: body === undefined ? undefined : JSON.stringify(body),
    });
  } catch (e) {
    throw new ApiError(`the server does not answer (${e.message})`);
  }
  return json(response);
}

export const info = () => call('GET', '/api/info');
export const listJobs = () => call('GET', '/api/jobs');
export const job = (id) => call('GET', `/api/jobs/${id}`);
export const slice = (id, options) => call('POST', `/api/jobs/${id}/slice`, options);
export const cancel = (id) => call('POST', `/api/jobs/${id}/cancel`, {});
export const validate = (id, options) => call('POST', `/api/jobs/${id}/validate`, options);
export const remove = (id) => call('DELETE', `/api/jobs/${id}`);
export const fileUrl = (id, kind) => `/api/jobs/${id}/files/${kind}`;
export const viewerUrl = (id) => `/viewer?job=${id}`;

/** Uploads a File; onProgress(fraction). Resolves to {id}. */
export function upload(file, onProgress) {
  return new Promise((resolve, reject) => {
    const xhr = new XMLHttpRequest();
    xhr.open('POST', `/api/jobs?name=${encodeURIComponent(file.name)}`);
    xhr.responseType = 'json';
    xhr.upload.onprogress = (e) => {
      if (e.lengthComputable) onProgress?.(e.loaded / e.total);
    };
    xhr.onload = () => {
      if (xhr.status >= 200 && xhr.status < 300 && xhr.response?.id) resolve(xhr.response);
      else reject(new ApiError(xhr.response?.error ?? `the server answered ${xhr.status}`));
    };
    xhr.onerror = () => reject(new ApiError('the upload failed: the server closed the connection'));
    xhr.send(file);
  });
}
