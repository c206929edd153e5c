const float kAmbientScale = 0.8;
vec3 broken() { return undefinedColor; }
