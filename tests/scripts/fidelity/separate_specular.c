/* GL 1.2 LIGHT_MODEL_COLOR_CONTROL: a lit quad textured dark under MODULATE, drawn twice.
   Left, SINGLE_COLOR: the specular highlight is in the primary colour, so the texture
   darkens it. Right, SEPARATE_SPECULAR_COLOR: the specular is the secondary colour, added
   after the texture environment (colour sum, GL 1.2 3.9): the highlight stays bright.
   A positional light over the middle of each quad, shininess 8, white specular. */
glClearColor(0, 0, 0, 1);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(-2, 2, -1, 1, -4, 4);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glBindTexture(GL_TEXTURE_2D, 1);
/* Rows of 2 texels are not 4-byte aligned: the pixels are packed. */
glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, (GLubyte[]){96,48,32, 32,96,48, 48,32,96, 96,96,32});
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
glEnable(GL_TEXTURE_2D);
glEnable(GL_LIGHTING);
glEnable(GL_LIGHT0);
glLightfv(GL_LIGHT0, GL_SPECULAR, (GLfloat[]){1, 1, 1, 1});
glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, (GLfloat[]){1, 1, 1, 1});
glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8);
glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){-1, 0, 1.5f, 1});
glBegin(GL_QUADS);
glNormal3f(0, 0, 1);
glTexCoord2f(0, 0); glVertex2f(-2, -1); glTexCoord2f(1, 0); glVertex2f(0, -1); glTexCoord2f(1, 1); glVertex2f(0, 1); glTexCoord2f(0, 1); glVertex2f(-2, 1);
glEnd();
glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){1, 0, 1.5f, 1});
glBegin(GL_QUADS);
glNormal3f(0, 0, 1);
glTexCoord2f(0, 0); glVertex2f(0, -1); glTexCoord2f(1, 0); glVertex2f(2, -1); glTexCoord2f(1, 1); glVertex2f(2, 1); glTexCoord2f(0, 1); glVertex2f(0, 1);
glEnd();
