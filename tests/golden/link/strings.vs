void main() { uv = gl_MultiTexCoord0.xy; gl_Position = ftransform(); }
