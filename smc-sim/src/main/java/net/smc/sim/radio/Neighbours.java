package net.smc.sim.radio;

import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Arrays;
import java.util.Iterator;
import java.util.NoSuchElementException;
import java.util.Set;

/**
 * A robot's neighbour table as an unmodifiable map from id to link quality, ids in ascending
 * order, held in two arrays: built once per robot and step, it costs no hashing or tree nodes.
 */
final class Neighbours extends AbstractMap<String, Double> {
    private final String[] ids;      // ascending; the first size entries are used
    private final double[] qualities;
    private final int size;

    Neighbours(String[] ids, double[] qualities, int size) {
        this.ids = ids;
        this.qualities = qualities;
        this.size = size;
    }

    @Override
    public int size() {
        return size;
    }

    @Override
    public boolean containsKey(Object key) {
        return indexOf(key) >= 0;
    }

    @Override
    public Double get(Object key) {
        int i = indexOf(key);
        return i < 0 ? null : qualities[i];
    }

    private int indexOf(Object key) {
        return key instanceof String id ? Math.max(-1, Arrays.binarySearch(ids, 0, size, id)) : -1;
    }

    @Override
    public Set<Entry<String, Double>> entrySet() {
        return new AbstractSet<>() {
            @Override
            public int size() {
                return size;
            }

            @Override
            public Iterator<Entry<String, Double>> iterator() {
                return new Iterator<>() {
                    private int next;

                    @Override
                    public boolean hasNext() {
                        return next < size;
                    }

                    @Override
                    public Entry<String, Double> next() {
                        if (next >= size) {
                            throw new NoSuchElementException();
                        }
                        int i = next++;
                        return new SimpleImmutableEntry<>(ids[i], qualities[i]);
                    }
                };
            }
        };
    }
}
