#include <SDL.h>
SDL_RWops* open_image(const char* path) { return SDL_RWFromFile(path, "rb"); }
SDL_Surface* picture(const char* path) { return SDL_LoadBMP(path); }
