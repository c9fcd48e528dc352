#version 430 core
// vtkHAVS: full-viewport quad for the per-pixel passes (clear, flush, resolve,
// composite). The quad's corners come in NDC.
in vec4 ndCoordIn;

void main()
{
  gl_Position = ndCoordIn;
}
