/* One texture unit (unit 2) enabled: the generated program holds no code for the others. */
glActiveTexture(GL_TEXTURE2);
glBindTexture(GL_TEXTURE_2D, 5);
/* Rows of 2 texels are not 4-byte aligned: the pixels are packed. */
glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, (GLubyte[]){0, 85, 170, 255});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glEnable(GL_TEXTURE_2D);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
glColor4f(1, 0.5f, 1, 1);
glBegin(GL_QUADS);
glMultiTexCoord2f(GL_TEXTURE2, 0, 0); glVertex3f(-1, -1, 0);
glMultiTexCoord2f(GL_TEXTURE2, 1, 0); glVertex3f(1, -1, 0);
glMultiTexCoord2f(GL_TEXTURE2, 1, 1); glVertex3f(1, 1, 0);
glMultiTexCoord2f(GL_TEXTURE2, 0, 1); glVertex3f(-1, 1, 0);
glEnd();
